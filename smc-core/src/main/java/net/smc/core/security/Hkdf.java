package net.smc.core.security;

import java.security.GeneralSecurityException;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * HKDF over HMAC-SHA256 (RFC 5869): turns one secret with uneven entropy (an X25519 shared
 * secret, a random team key) into several independent keys, each bound by {@code info} to one
 * purpose and one pair of vehicles. The JDK 17 has HMAC but no HKDF, so here are the RFC's two
 * steps in a few lines; {@code HkdfTest} checks them against the RFC's test vectors.
 */
final class Hkdf {
    static final int HASH_BYTES = 32;
    private static final String HMAC = "HmacSHA256";

    private Hkdf() {
    }

    /** Extract then expand: {@code length} bytes of keying material. */
    static byte[] derive(byte[] salt, byte[] ikm, byte[] info, int length) {
        return expand(extract(salt, ikm), info, length);
    }

    /** The pseudo-random key; a null or empty salt means {@value #HASH_BYTES} zero bytes, as the RFC says. */
    static byte[] extract(byte[] salt, byte[] ikm) {
        byte[] key = salt == null || salt.length == 0 ? new byte[HASH_BYTES] : salt;
        return hmac(key).doFinal(ikm);
    }

    /**
     * {@code length} bytes from the pseudo-random key {@code prk}.
     *
     * @throws IllegalArgumentException when {@code length} is not 0 to 255 * 32, the RFC's limit
     */
    static byte[] expand(byte[] prk, byte[] info, int length) {
        if (length < 0 || length > 255 * HASH_BYTES) {
            throw new IllegalArgumentException("HKDF output length " + length + " is out of range; it must be 0 to " + 255 * HASH_BYTES);
        }
        Mac mac = hmac(prk);
        byte[] okm = new byte[length];
        byte[] t = new byte[0];
        for (int i = 1, done = 0; done < length; i++) {
            mac.update(t);
            mac.update(info);
            mac.update((byte) i);
            t = mac.doFinal();
            int n = Math.min(t.length, length - done);
            System.arraycopy(t, 0, okm, done, n);
            done += n;
        }
        return okm;
    }

    /** An HMAC-SHA256 keyed with {@code key}. */
    static Mac hmac(byte[] key) {
        try {
            Mac mac = Mac.getInstance(HMAC);
            mac.init(new SecretKeySpec(key, HMAC));
            return mac;
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("the JDK must provide " + HMAC, e);
        }
    }
}
