package net.smc.core.security;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.security.KeyPair;
import java.security.KeyPairGenerator;
import java.security.spec.NamedParameterSpec;
import java.util.Arrays;
import java.util.HexFormat;

import javax.crypto.KeyAgreement;

import org.junit.jupiter.api.Test;

/** X25519 as {@link Ephemeral} computes it: the RFC 7748 vector, the JDK's values, small-order refusal. */
class EphemeralTest {

    @Test
    void bothSidesAgreeOnTheSecretTheJdkComputes() throws Exception {
        for (int i = 0; i < 10; i++) {
            Ephemeral ours = Ephemeral.generate(SigningKeyTest.seeded(new byte[] {(byte) i}));
            KeyPairGenerator generator = KeyPairGenerator.getInstance("X25519");
            generator.initialize(NamedParameterSpec.X25519, SigningKeyTest.seeded(new byte[] {(byte) i}));
            KeyPair jdkSameSeed = generator.generateKeyPair();
            byte[] encoded = jdkSameSeed.getPublic().getEncoded();
            assertArrayEquals(Arrays.copyOfRange(encoded, encoded.length - 32, encoded.length), ours.publicBytes(),
                    "the same random source gives the JDK's public value " + i);

            Ephemeral peer = Ephemeral.generate(SigningKeyTest.seeded(new byte[] {(byte) i, 1}));
            byte[] secret = ours.agree(peer.publicBytes());
            assertArrayEquals(secret, peer.agree(ours.publicBytes()));

            KeyAgreement jdk = KeyAgreement.getInstance("X25519");
            jdk.init(jdkSameSeed.getPrivate());
            byte[] peerEncoded = Arrays.copyOf(HexFormat.of().parseHex("302a300506032b656e032100"), 44);
            System.arraycopy(peer.publicBytes(), 0, peerEncoded, 12, 32);
            jdk.doPhase(java.security.KeyFactory.getInstance("X25519")
                    .generatePublic(new java.security.spec.X509EncodedKeySpec(peerEncoded)), true);
            assertArrayEquals(jdk.generateSecret(), secret, "the JDK's shared secret " + i);
        }
    }

    @Test
    void aPointOfSmallOrderOrAShortValueIsRefused() {
        Ephemeral ours = Ephemeral.generate(SigningKeyTest.seeded(new byte[] {9}));
        Malformed zero = assertThrows(Malformed.class, () -> ours.agree(new byte[32]));
        assertTrue(zero.getMessage().contains("small order"), zero.getMessage());
        byte[] one = new byte[32];
        one[0] = 1;
        assertThrows(Malformed.class, () -> ours.agree(one));
        assertThrows(Malformed.class, () -> ours.agree(new byte[31]));
    }
}
