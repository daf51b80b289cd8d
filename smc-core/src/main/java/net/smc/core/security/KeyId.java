package net.smc.core.security;

import java.nio.ByteBuffer;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

/**
 * A short name for an Ed25519 public key: the first 8 bytes of its SHA-256. A credential names
 * the authority that signed it by this id, so a vehicle can tell "signed by another authority"
 * from "signed badly" without trying every key it trusts.
 *
 * @param value the 8 bytes, big-endian
 */
public record KeyId(long value) {

    /** The id of a 32-byte raw public key. */
    static KeyId of(byte[] rawPublicKey) {
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256").digest(rawPublicKey);
            return new KeyId(ByteBuffer.wrap(digest).getLong());
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("the JDK must provide SHA-256", e);
        }
    }

    /** 16 lower-case hex digits. */
    @Override
    public String toString() {
        return HexFormat.of().toHexDigits(value);
    }
}
