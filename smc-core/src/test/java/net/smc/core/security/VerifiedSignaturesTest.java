package net.smc.core.security;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.security.SecureRandom;

import org.junit.jupiter.api.Test;

/**
 * The memo of valid signatures ({@link VerifiedSignatures}) answers as the arithmetic would: a
 * signature verified once is found again only with the same key, every same signed byte and every
 * same signature byte; any other bytes are verified afresh (and fail when they are not a signature).
 * Keys made from the same bytes are one object, decoded once.
 */
class VerifiedSignaturesTest {
    private static final SigningKey ALICE = SigningKey.generate(seeded(1));
    private static final SigningKey BOB = SigningKey.generate(seeded(2));

    @Test
    void theSameSignedBytesAreVerifiedOnceThenFoundAgain() {
        byte[] message = "discover: cdr, mission WoundedSoldier".getBytes(StandardCharsets.UTF_8);
        byte[] signature = ALICE.sign(message);
        long hits = VerifiedSignatures.SHARED.hits();
        assertTrue(ALICE.verificationKey().verify(message, signature));
        assertTrue(ALICE.verificationKey().verify(message.clone(), signature.clone()), "a second receiver's copy");
        assertTrue(VerificationKey.of(ALICE.verificationKey().bytes()).verify(message, signature), "the key decoded again");
        assertEquals(hits + 2, VerifiedSignatures.SHARED.hits(), "the second and third checks found the first");
    }

    @Test
    void anyOtherByteOfTheMessageOrSignatureOrKeyIsVerifiedAfreshAndFails() {
        byte[] message = "heading for the soldier at 11.0,4.3".getBytes(StandardCharsets.UTF_8);
        byte[] signature = ALICE.sign(message);
        VerificationKey alice = ALICE.verificationKey();
        assertTrue(alice.verify(message, signature));
        for (int i = 0; i < message.length; i++) {
            byte[] forged = message.clone();
            forged[i] ^= 1 << (i % 8);
            assertFalse(alice.verify(forged, signature), "message byte " + i + " changed");
        }
        for (int i = 0; i < signature.length; i++) {
            byte[] forged = signature.clone();
            forged[i] ^= 1 << (i % 8);
            assertFalse(alice.verify(message, forged), "signature byte " + i + " changed");
        }
        assertFalse(BOB.verificationKey().verify(message, signature), "another vehicle's key");
        byte[] longer = java.util.Arrays.copyOf(message, message.length + 1);
        assertFalse(alice.verify(longer, signature), "a byte appended");
        byte[] shorter = java.util.Arrays.copyOf(message, message.length - 1);
        assertFalse(alice.verify(shorter, signature), "the last byte cut");
        assertTrue(alice.verify(message, signature), "the genuine bytes still verify");
    }

    @Test
    void aFailedVerificationIsNotRemembered() {
        byte[] message = "not signed by bob".getBytes(StandardCharsets.UTF_8);
        byte[] signature = ALICE.sign(message);
        VerificationKey bob = BOB.verificationKey();
        assertFalse(bob.verify(message, signature));
        assertFalse(VerifiedSignatures.SHARED.contains(bob, message, 0, message.length, signature, 0));
        assertFalse(bob.verify(message, signature));
    }

    @Test
    void keepsOnlyTheMostRecentlyUsedEntries() {
        VerifiedSignatures memo = new VerifiedSignatures(2);
        byte[][] messages = {{1}, {2}, {3}};
        byte[][] signatures = new byte[3][];
        for (int i = 0; i < 3; i++) {
            signatures[i] = ALICE.sign(messages[i]);
        }
        VerificationKey alice = ALICE.verificationKey();
        memo.add(alice, messages[0], 0, 1, signatures[0], 0);
        memo.add(alice, messages[1], 0, 1, signatures[1], 0);
        assertTrue(memo.contains(alice, messages[0], 0, 1, signatures[0], 0), "used: now the most recent");
        memo.add(alice, messages[2], 0, 1, signatures[2], 0);
        assertEquals(2, memo.size());
        assertTrue(memo.contains(alice, messages[0], 0, 1, signatures[0], 0));
        assertFalse(memo.contains(alice, messages[1], 0, 1, signatures[1], 0), "the least recently used went");
        assertTrue(memo.contains(alice, messages[2], 0, 1, signatures[2], 0));
    }

    @Test
    void anEntryIsACopyNotTheCallersBytes() {
        VerifiedSignatures memo = new VerifiedSignatures(4);
        byte[] message = {5, 6, 7};
        byte[] signature = ALICE.sign(message);
        VerificationKey alice = ALICE.verificationKey();
        memo.add(alice, message, 0, 3, signature, 0);
        message[1] = 9;
        assertFalse(memo.contains(alice, message, 0, 3, signature, 0), "the caller changed its array afterwards");
        assertTrue(memo.contains(alice, new byte[] {5, 6, 7}, 0, 3, signature, 0));
    }

    @Test
    void keysFromTheSameBytesAreOneObjectAndKeepTheirOwnCopy() {
        byte[] raw = BOB.verificationKey().bytes();
        VerificationKey first = VerificationKey.of(raw);
        raw[0] ^= 1;
        VerificationKey other = VerificationKey.of(raw);
        raw[0] ^= 1;
        assertSame(first, VerificationKey.of(raw));
        assertArrayEquals(BOB.verificationKey().bytes(), first.bytes());
        assertFalse(first.equals(other));
    }

    private static SecureRandom seeded(int seed) {
        try {
            SecureRandom r = SecureRandom.getInstance("SHA1PRNG");
            r.setSeed(seed);
            return r;
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
