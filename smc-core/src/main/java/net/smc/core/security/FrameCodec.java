package net.smc.core.security;

import java.nio.ByteBuffer;

/**
 * The wire form of protected datagrams, version 1: what {@link SecureEndpoint} puts around a
 * payload and reads back. Every datagram starts with the version and a kind byte; integers are
 * big-endian; a name is one length byte (1..64) then UTF-8; "cred" is a credential in its binary
 * form ({@code CredentialCodec}) after one length byte.
 *
 * <pre>
 * kind          layout after version and kind                                tag
 * 1 SIGNED      ts:8 ctr:8 cred payload                                       Ed25519 sig:64 of all before
 * 2 HELLO       ts:8 ctr:8 cred recipient:name eph:32 echo:32                 Ed25519 sig:64 of all before
 * 3 PAIR_MAC    sender:name ts:8 ctr:8 payload                                HMAC-SHA256/128:16 of all before
 * 4 TEAM_MAC    teamKeyId:4 sender:name ts:8 ctr:8 payload                    HMAC-SHA256/128:16 of all before
 * 5 TEAM_KEY    sender:name ts:8 ctr:8 AES-256-GCM(team key:32), tag:16       (GCM tag; all before is AAD)
 * </pre>
 *
 * <p>A HELLO's eph is the sender's X25519 public value for this peer; echo is the peer's value as
 * the sender last saw it, or 32 zero bytes if it has seen none.
 *
 * <p>ts is the sender's clock in epoch ms, ctr its counter. A signed kind names its sender through
 * its credential; the keyed kinds name it directly, and the key proves it.
 */
final class FrameCodec {
    static final int VERSION = 1;
    static final int SIGNED = 1;
    static final int HELLO = 2;
    static final int PAIR_MAC = 3;
    static final int TEAM_MAC = 4;
    static final int TEAM_KEY = 5;
    static final int TEAM_ID_BYTES = 4;
    static final int TEAM_KEY_BYTES = 32;
    static final int GCM_TAG_BYTES = 16;
    static final int SIG = SigningKey.SIGNATURE_BYTES;
    static final int MAC = TruncatedMac.BYTES;
    private static final int HEAD = 2 + 8 + 8;   // version, kind, timestamp, counter

    private FrameCodec() {
    }

    static int signedOverhead(int credentialBytes) {
        return HEAD + 1 + credentialBytes + SIG;
    }

    static int pairOverhead(int senderBytes) {
        return HEAD + 1 + senderBytes + MAC;
    }

    static int teamOverhead(int senderBytes) {
        return HEAD + TEAM_ID_BYTES + 1 + senderBytes + MAC;
    }

    static String kindName(int kind) {
        return switch (kind) {
            case SIGNED -> "signed datagram";
            case HELLO -> "handshake";
            case PAIR_MAC -> "pair-MAC datagram";
            case TEAM_MAC -> "team-MAC datagram";
            case TEAM_KEY -> "team key";
            default -> "datagram of kind " + kind;
        };
    }

    /** A SIGNED datagram with room for the signature at its end, not yet signed. */
    static byte[] signed(byte[] credential, long timestampMillis, long counter, byte[] payload) {
        ByteBuffer out = ByteBuffer.allocate(signedOverhead(credential.length) + payload.length);
        head(out, SIGNED, timestampMillis, counter).put((byte) credential.length).put(credential).put(payload);
        return out.array();
    }

    /** A HELLO with room for the signature, not yet signed; a null {@code echo} is written as zeros. */
    static byte[] hello(byte[] credential, long timestampMillis, long counter, byte[] recipient, byte[] ephemeral, byte[] echo) {
        int size = HEAD + 1 + credential.length + 1 + recipient.length + 2 * Ephemeral.BYTES + SIG;
        ByteBuffer out = ByteBuffer.allocate(size);
        head(out, HELLO, timestampMillis, counter).put((byte) credential.length).put(credential)
                .put((byte) recipient.length).put(recipient).put(ephemeral).put(echo == null ? new byte[Ephemeral.BYTES] : echo);
        return out.array();
    }

    /**
     * A PAIR_MAC, TEAM_MAC or TEAM_KEY datagram: header, then {@code body}, then {@code tagBytes} of
     * room for the MAC ({@code body} of a TEAM_KEY is the sealed key, tag included, so 0 more).
     */
    static byte[] keyed(int kind, int teamId, byte[] sender, long timestampMillis, long counter, byte[] body, int tagBytes) {
        ByteBuffer out = ByteBuffer.allocate(keyedHeaderBytes(kind, sender.length) + body.length + tagBytes);
        out.put((byte) VERSION).put((byte) kind);
        if (kind == TEAM_MAC) {
            out.putInt(teamId);
        }
        out.put((byte) sender.length).put(sender).putLong(timestampMillis).putLong(counter).put(body);
        return out.array();
    }

    /** The bytes before the body of a keyed kind: what a TEAM_KEY's seal takes as associated data. */
    static int keyedHeaderBytes(int kind, int senderBytes) {
        return HEAD + 1 + senderBytes + (kind == TEAM_MAC ? TEAM_ID_BYTES : 0);
    }

    private static ByteBuffer head(ByteBuffer out, int kind, long timestampMillis, long counter) {
        return out.put((byte) VERSION).put((byte) kind).putLong(timestampMillis).putLong(counter);
    }

    /**
     * Parses a datagram. Checks only the form (lengths, limits, UTF-8); no key is used.
     *
     * @throws Malformed naming the kind, the field, its offset and the rule
     */
    static Frame read(byte[] datagram) throws Malformed {
        WireIn head = new WireIn(datagram, 0, datagram.length, "datagram");
        int version = head.u8("version");
        if (version != VERSION) {
            throw head.error(0, "version", version + " is not a known version; this reader knows " + VERSION);
        }
        int kind = head.u8("kind");
        return switch (kind) {
            case SIGNED, HELLO -> readSigned(datagram, kind);
            case PAIR_MAC, TEAM_MAC, TEAM_KEY -> readKeyed(datagram, kind);
            default -> throw head.error(1, "kind", kind + " is not a known kind; they are 1 to 5");
        };
    }

    private static Frame readSigned(byte[] datagram, int kind) throws Malformed {
        String what = kindName(kind);
        int signedLength = datagram.length - SIG;
        if (signedLength < HEAD + 1) {
            throw new Malformed(what + ": " + datagram.length + " bytes is too short to hold a header and a signature");
        }
        WireIn in = new WireIn(datagram, 2, signedLength, what);
        long timestamp = in.i64("timestamp");
        long counter = in.i64("counter");
        int credentialLength = in.u8("credential length");
        int at = in.position();
        in.skip(credentialLength, "credential");
        Credential credential;
        try {
            credential = CredentialCodec.decode(datagram, at, credentialLength);
        } catch (Malformed e) {
            throw new Malformed(what + ": " + e.getMessage());
        }
        if (kind == SIGNED) {
            return new Frame.Signed(credential, timestamp, counter, datagram, in.position(), signedLength);
        }
        String recipient = in.name("recipient");
        byte[] ephemeral = in.bytes(Ephemeral.BYTES, "ephemeral key");
        byte[] echo = in.bytes(Ephemeral.BYTES, "echoed ephemeral key");
        if (in.remaining() != 0) {
            throw in.error(in.offset(), "signature", "found " + (in.remaining() + SIG) + " bytes; it is " + SIG);
        }
        return new Frame.Hello(credential, timestamp, counter, recipient, ephemeral, echo, datagram, signedLength);
    }

    private static Frame readKeyed(byte[] datagram, int kind) throws Malformed {
        String what = kindName(kind);
        WireIn in = new WireIn(datagram, 2, datagram.length, what);
        int teamId = kind == TEAM_MAC ? in.i32("team key id") : 0;
        String sender = in.name("sender");
        long timestamp = in.i64("timestamp");
        long counter = in.i64("counter");
        int bodyStart = in.position();
        int bodyEnd;
        if (kind == TEAM_KEY) {
            bodyEnd = bodyStart + TEAM_KEY_BYTES + GCM_TAG_BYTES;
            if (datagram.length != bodyEnd) {
                throw in.error(in.offset(), "sealed team key", "found " + in.remaining() + " bytes; it is "
                        + (TEAM_KEY_BYTES + GCM_TAG_BYTES));
            }
        } else {
            bodyEnd = datagram.length - MAC;
            if (bodyEnd < bodyStart) {
                throw in.error(in.offset(), "MAC", "truncated: needs " + MAC + " bytes, " + in.remaining() + " left");
            }
        }
        return new Frame.Keyed(kind, teamId, sender, timestamp, counter, datagram, bodyStart, bodyEnd);
    }
}
