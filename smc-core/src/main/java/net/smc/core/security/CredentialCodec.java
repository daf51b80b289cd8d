package net.smc.core.security;

import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;

/**
 * The binary form of a {@link Credential}, version 1 (big-endian):
 *
 * <pre>
 * size  field
 * 1     version = 1
 * 1+n   vehicle id: length n (1..64), UTF-8
 * 32    vehicle public key, raw Ed25519
 * 1+m   mission: length m (1..64), UTF-8
 * 8     not-before, epoch ms (signed)
 * 8     expires, epoch ms (signed)
 * 8     authority key id (first 8 bytes of the SHA-256 of the authority's raw public key)
 * 64    Ed25519 signature by the authority of CONTEXT || every byte above
 * </pre>
 *
 * <p>123 + n + m bytes, so at most {@value #MAX_BYTES}: the length fits the one byte an envelope
 * gives it. The signature covers a context string first, so that no other signed form of the
 * project can be passed off as a credential.
 */
final class CredentialCodec {
    static final int VERSION = 1;
    static final int FIXED_BYTES = 1 + 1 + VerificationKey.BYTES + 1 + 8 + 8 + 8 + SigningKey.SIGNATURE_BYTES;
    static final int MAX_BYTES = FIXED_BYTES + 2 * WireNames.MAX_BYTES;
    private static final byte[] CONTEXT = "smc-credential-v1\0".getBytes(StandardCharsets.US_ASCII);

    private CredentialCodec() {
    }

    /** The signed part of the form: everything but the signature. */
    static byte[] body(Claims claims, KeyId authority) {
        byte[] id = WireNames.encode(claims.vehicleId(), "credential", "vehicle id");
        byte[] mission = WireNames.encode(claims.mission(), "credential", "mission");
        ByteBuffer out = ByteBuffer.allocate(FIXED_BYTES - SigningKey.SIGNATURE_BYTES + id.length + mission.length);
        out.put((byte) VERSION).put((byte) id.length).put(id).put(claims.vehicleKey().bytes())
                .put((byte) mission.length).put(mission)
                .putLong(claims.notBeforeMillis()).putLong(claims.expiresMillis()).putLong(authority.value());
        return out.array();
    }

    /** What the authority signs: the context, then the body. */
    static byte[] toBeSigned(byte[] body) {
        byte[] out = new byte[CONTEXT.length + body.length];
        System.arraycopy(CONTEXT, 0, out, 0, CONTEXT.length);
        System.arraycopy(body, 0, out, CONTEXT.length, body.length);
        return out;
    }

    static byte[] encode(Credential credential) {
        byte[] body = body(credential.claims(), credential.authority());
        byte[] out = new byte[body.length + SigningKey.SIGNATURE_BYTES];
        System.arraycopy(body, 0, out, 0, body.length);
        System.arraycopy(credential.signature(), 0, out, body.length, SigningKey.SIGNATURE_BYTES);
        return out;
    }

    /** Reads exactly {@code data[offset, offset + length)} as a credential. */
    static Credential decode(byte[] data, int offset, int length) throws Malformed {
        WireIn in = new WireIn(data, offset, offset + length, "credential");
        if (length > MAX_BYTES) {
            throw in.error(0, "credential", length + " bytes; the limit is " + MAX_BYTES);
        }
        int version = in.u8("version");
        if (version != VERSION) {
            throw in.error(0, "version", version + " is not a known version; this reader knows " + VERSION);
        }
        String vehicleId = in.name("vehicle id");
        int keyAt = in.offset();
        byte[] key = in.bytes(VerificationKey.BYTES, "vehicle key");
        String mission = in.name("mission");
        int timesAt = in.offset();
        long notBefore = in.i64("not-before");
        long expires = in.i64("expires");
        KeyId authority = new KeyId(in.i64("authority key id"));
        byte[] signature = in.bytes(SigningKey.SIGNATURE_BYTES, "signature");
        if (in.remaining() != 0) {
            throw in.error(in.offset(), "end", in.remaining() + " bytes after the signature; a credential ends with it");
        }
        if (expires <= notBefore) {
            throw in.error(timesAt, "expires", expires + " is not after not-before " + notBefore);
        }
        VerificationKey vehicleKey;
        try {
            vehicleKey = VerificationKey.of(key);
        } catch (IllegalArgumentException e) {
            throw in.error(keyAt, "vehicle key", e.getMessage());
        }
        return new Credential(new Claims(vehicleId, vehicleKey, mission, notBefore, expires), authority, signature);
    }
}
