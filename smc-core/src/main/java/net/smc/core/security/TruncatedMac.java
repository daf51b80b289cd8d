package net.smc.core.security;

import javax.crypto.Mac;
import javax.crypto.ShortBufferException;
import net.smc.core.wire.ByteWriter;

/**
 * HMAC-SHA256 cut to its first {@value #BYTES} bytes, 80 bits: the least RFC 2104 (section 5)
 * advises keeping and the tag SRTP puts on every real-time media packet (RFC 3711,
 * HMAC-SHA1-80). A forger has one chance in 2^80 per try, and each try is a datagram the receiver
 * must hear: at a million tries a second, some 38 billion years a success. A tag can be checked
 * only with the key, so no try can be made off line. Against the full 32 bytes, 22 fewer on every
 * heartbeat and its echo, the bulk of a settled team's traffic. One keyed {@link Mac} is kept and
 * reused, since keying costs more than MAC-ing a heartbeat; so an instance belongs to one thread,
 * as its endpoint does.
 */
final class TruncatedMac {
    static final int BYTES = 10;

    private final Mac mac;
    private final byte[] full = new byte[Hkdf.HASH_BYTES];
    private final byte[] counterBytes = new byte[Long.BYTES];

    TruncatedMac(byte[] key) {
        this.mac = Hkdf.hmac(key);
    }

    /** Writes the MAC of the full {@code counter} and {@code data[0, length)} into {@code data[length, length + BYTES)}. */
    void sign(long counter, byte[] data, int length) {
        compute(counter, data, length);
        System.arraycopy(full, 0, data, length, BYTES);
    }

    /** Whether {@code data[length, length + BYTES)} is the MAC of the full {@code counter} and {@code data[0, length)}; in constant time. */
    boolean verify(long counter, byte[] data, int length) {
        compute(counter, data, length);
        int diff = 0;
        for (int i = 0; i < BYTES; i++) {
            diff |= full[i] ^ data[length + i];
        }
        return diff == 0;
    }

    private void compute(long counter, byte[] data, int length) {
        ByteWriter.putI64(counterBytes, 0, counter);
        mac.update(counterBytes);
        mac.update(data, 0, length);
        try {
            mac.doFinal(full, 0);
        } catch (ShortBufferException e) {
            throw new AssertionError("a 32-byte buffer holds an HMAC-SHA256", e);
        }
    }
}
