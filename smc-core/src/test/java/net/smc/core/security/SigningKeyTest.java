package net.smc.core.security;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.security.GeneralSecurityException;
import java.security.KeyPair;
import java.security.KeyPairGenerator;
import java.security.SecureRandom;
import java.security.Signature;
import java.security.interfaces.EdECPrivateKey;
import java.security.spec.NamedParameterSpec;
import java.util.HexFormat;
import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * Ed25519 as {@link SigningKey} and {@link VerificationKey} compute it: the RFC 8032 test vectors,
 * and the same keys and signatures as the JDK's own provider, both ways, on random keys and messages.
 */
class SigningKeyTest {
    private static final HexFormat HEX = HexFormat.of();

    /** RFC 8032, section 7.1, tests 1 to 3: seed, public key, message, signature. */
    private static final String[][] RFC_8032 = {
        {"9d61b19deffd5a60ba844af492ec2cc44449c5697b326919703bac031cae7f60",
            "d75a980182b10ab7d54bfed3c964073a0ee172f3daa62325af021a68f707511a", "",
            "e5564300c360ac729086e2cc806e828a84877f1eb8e5d974d873e065224901555fb8821590a33bacc61e39701cf9b46b"
                + "d25bf5f0595bbe24655141438e7a100b"},
        {"4ccd089b28ff96da9db6c346ec114e0f5b8a319f35aba624da8cf6ed4fb8a6fb",
            "3d4017c3e843895a92b70aa74d1b7ebc9c982ccf2ec4968cc0cd55f12af4660c", "72",
            "92a009a9f0d4cab8720e820b5f642540a2b27b5416503f8fb3762223ebdb69da085ac1e43e15996e458f3613d0f11d8c"
                + "387b2eaeb4302aeeb00d291612bb0c00"},
        {"c5aa8df43f9f837bedb7442f31dcb7b166d38535076f094b85ce3a2e0b4458f7",
            "fc51cd8e6218a1a38da47ed00230f0580816ed13ba3303ac5deb911548908025", "af82",
            "6291d657deec24024827e69c3abe01a30ce548a284743a445e3680d7db5ac3ac18ff9b538d16f290ae67f760984dc659"
                + "4a7c15e9716ed28dc027beceea1ec40a"},
    };

    @Test
    void signsAndVerifiesTheRfc8032Vectors() {
        for (String[] v : RFC_8032) {
            VerificationKey publicKey = VerificationKey.of(HEX.parseHex(v[1]));
            SigningKey key = SigningKey.of(HEX.parseHex(v[0]), publicKey);
            byte[] message = HEX.parseHex(v[2]);
            assertArrayEquals(HEX.parseHex(v[3]), key.sign(message), "signature of '" + v[2] + "'");
            assertTrue(publicKey.verify(message, HEX.parseHex(v[3])));
        }
    }

    @Test
    void aSeededGeneratorGivesTheKeyPairTheJdkGivesAndTheSameSignatures() throws GeneralSecurityException {
        Random sizes = new Random(7);
        for (int i = 0; i < 20; i++) {
            byte[] seedOfRandom = {(byte) i, 42};
            SigningKey ours = SigningKey.generate(seeded(seedOfRandom));
            KeyPairGenerator jdk = KeyPairGenerator.getInstance("Ed25519");
            jdk.initialize(NamedParameterSpec.ED25519, seeded(seedOfRandom));
            KeyPair theirs = jdk.generateKeyPair();
            assertArrayEquals(((EdECPrivateKey) theirs.getPrivate()).getBytes().orElseThrow(), ours.seed(), "seed " + i);

            byte[] message = new byte[sizes.nextInt(1400)];
            sizes.nextBytes(message);
            Signature signer = Signature.getInstance("Ed25519");
            signer.initSign(theirs.getPrivate());
            signer.update(message);
            byte[] jdkSignature = signer.sign();
            assertArrayEquals(jdkSignature, ours.sign(message), "signature " + i);

            Signature verifier = Signature.getInstance("Ed25519");
            verifier.initVerify(theirs.getPublic());
            verifier.update(message);
            assertTrue(verifier.verify(ours.sign(message)), "the JDK verifies our signature " + i);
            assertTrue(ours.verificationKey().verify(message, jdkSignature), "we verify the JDK's signature " + i);
        }
    }

    @Test
    void aChangedMessageSignatureOrKeyDoesNotVerify() {
        SigningKey key = SigningKey.generate(seeded(new byte[] {3}));
        byte[] message = "role assignment".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        byte[] signature = key.sign(message);
        assertTrue(key.verificationKey().verify(message, signature));

        byte[] otherMessage = message.clone();
        otherMessage[0] ^= 1;
        assertFalse(key.verificationKey().verify(otherMessage, signature));
        for (int bit : new int[] {0, 100, 255, 511}) {
            byte[] flipped = signature.clone();
            flipped[bit / 8] ^= (byte) (1 << (bit % 8));
            assertFalse(key.verificationKey().verify(message, flipped), "signature bit " + bit);
        }
        assertFalse(SigningKey.generate(seeded(new byte[] {4})).verificationKey().verify(message, signature));
        assertFalse(key.verificationKey().verify(message, new byte[10]), "a short signature");
        assertFalse(key.verificationKey().verify(message, 0, message.length, signature, 1), "a signature cut short by its offset");
    }

    @Test
    void bytesThatAreNoPointMakeAKeyThatVerifiesNothing() {
        // y = 2 gives x^2 = 3 / (1 + 2d), which has no square root: no point of the curve
        byte[] noPoint = new byte[VerificationKey.BYTES];
        noPoint[0] = 2;
        VerificationKey key = VerificationKey.of(noPoint);
        assertFalse(key.verify(new byte[] {1}, new byte[SigningKey.SIGNATURE_BYTES]));
        assertEquals(key, VerificationKey.of(noPoint.clone()));
    }

    @Test
    void aSeedWithAnotherPublicKeyIsRefused() {
        SigningKey a = SigningKey.generate(seeded(new byte[] {5}));
        SigningKey b = SigningKey.generate(seeded(new byte[] {6}));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SigningKey.of(a.seed(), b.verificationKey()));
        assertEquals("the public key " + b.verificationKey().id() + " is not the pair of the private key it came with", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> SigningKey.of(new byte[31], a.verificationKey()));
        assertThrows(IllegalArgumentException.class, () -> VerificationKey.of(new byte[33]));
    }

    /** A SHA1PRNG seeded with {@code seed} alone: the same bytes on every run (also for {@code EphemeralTest}). */
    static SecureRandom seeded(byte[] seed) {
        try {
            SecureRandom random = SecureRandom.getInstance("SHA1PRNG");
            random.setSeed(seed);
            return random;
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException(e);
        }
    }
}
