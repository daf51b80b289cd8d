package net.smc.core.security;

import java.security.GeneralSecurityException;
import java.util.Arrays;
import javax.crypto.AEADBadTagException;
import javax.crypto.Cipher;
import javax.crypto.spec.GCMParameterSpec;
import javax.crypto.spec.SecretKeySpec;

/**
 * AES-256-GCM for the one secret that travels: the team key, sealed under a session's key. The
 * nonce is 4 zero bytes then the sender's 8-byte counter, which never repeats under one session key.
 */
final class Seal {
    private Seal() {
    }

    static byte[] seal(byte[] key, long counter, byte[] aad, int aadLength, byte[] plaintext) {
        try {
            Cipher cipher = cipher(Cipher.ENCRYPT_MODE, key, counter);
            cipher.updateAAD(aad, 0, aadLength);
            return cipher.doFinal(plaintext);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("the JDK must provide AES-256-GCM", e);
        }
    }

    /** The plaintext, or null when the tag does not verify (altered, or another key). */
    static byte[] open(byte[] key, long counter, byte[] datagram, int aadLength, int end) {
        try {
            Cipher cipher = cipher(Cipher.DECRYPT_MODE, key, counter);
            cipher.updateAAD(datagram, 0, aadLength);
            return cipher.doFinal(datagram, aadLength, end - aadLength);
        } catch (AEADBadTagException e) {
            return null;
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("the JDK must provide AES-256-GCM", e);
        }
    }

    private static Cipher cipher(int mode, byte[] key, long counter) throws GeneralSecurityException {
        byte[] nonce = new byte[12];
        for (int i = 0; i < 8; i++) {
            nonce[4 + i] = (byte) (counter >>> (56 - 8 * i));
        }
        Cipher cipher = Cipher.getInstance("AES/GCM/NoPadding");
        cipher.init(mode, new SecretKeySpec(key, "AES"), new GCMParameterSpec(128, nonce));
        Arrays.fill(nonce, (byte) 0);
        return cipher;
    }
}
