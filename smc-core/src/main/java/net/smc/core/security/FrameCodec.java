package net.smc.core.security;

import net.smc.core.wire.ByteReader;
import net.smc.core.wire.ByteWriter;
import net.smc.core.wire.WireProblem;

/**
 * The wire form of protected datagrams, version 3: what {@link SecureEndpoint} puts around a
 * payload and reads back. Every datagram starts with the version and a kind byte; integers are
 * big-endian; a name is one length byte (1..64) then UTF-8; "cred" is a credential in its binary
 * form ({@code CredentialCodec}) after one length byte.
 *
 * <pre>
 * kind          layout after version and kind                                tag
 * 1 SIGNED      ctr:6 cred payload                                            Ed25519 sig:64
 * 2 HELLO       ctr:6 cred recipient:name eph:32 echo:32                      Ed25519 sig:64
 * 3 PAIR_MAC    sender:name ctr:6 payload                                     HMAC-SHA256/80:10
 * 4 TEAM_MAC    teamKeyId:4 sender:name ctr:6 payload                         HMAC-SHA256/80:10
 * 5 TEAM_KEY    sender:name ctr:6 AES-256-GCM(team key:32), tag:16            (GCM tag)
 * </pre>
 *
 * <p>A HELLO's eph is the sender's X25519 public value for this peer; echo is the peer's value as
 * the sender last saw it, or 32 zero bytes if it has seen none.
 *
 * <p>ctr is the low 48 bits of the sender's counter, which follows its clock ({@code max(last + 1,
 * clock << 20)}, see {@code SecureEndpoint}): so the counter's time is the sender's clock when it
 * sent, and no timestamp travels beside it. A receiver takes the full counter to be the one with
 * those low bits nearest its own clock shifted the same way; the 48 bits span 2^28 ms (three days)
 * of counter, so any counter within the freshness window (at most a day) is found, and one that is
 * not is refused as stale. The tag covers the full counter: a signature or MAC is computed over
 * {@code counter:8} followed by every byte of the datagram before the tag (for a TEAM_KEY the full
 * counter is the nonce, and those bytes the associated data). So a datagram replayed 2^28 ms later,
 * whose low bits would then name a counter 2^48 higher, does not verify.
 *
 * <p>A signed kind names its sender through its credential; the keyed kinds name it directly, and
 * the key proves it.
 */
final class FrameCodec {
    static final int VERSION = 3;
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
    /** The bytes of a counter on the wire: its low 48 bits. */
    static final int COUNTER_BYTES = 6;
    private static final int COUNTER_BITS = 8 * COUNTER_BYTES;
    private static final long COUNTER_MASK = (1L << COUNTER_BITS) - 1;
    private static final int HEAD = 2 + COUNTER_BYTES;   // version, kind, counter

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
    static byte[] signed(byte[] credential, long counter, byte[] payload) {
        ByteWriter out = CredentialCodec.exact(signedOverhead(credential.length) + payload.length);
        head(out, SIGNED, counter);
        out.u8(credential.length);
        out.bytes(credential);
        out.bytes(payload);
        return out.array();
    }

    /** A HELLO with room for the signature, not yet signed; a null {@code echo} is written as zeros. */
    static byte[] hello(byte[] credential, long counter, byte[] recipient, byte[] ephemeral, byte[] echo) {
        int size = HEAD + 1 + credential.length + 1 + recipient.length + 2 * Ephemeral.BYTES + SIG;
        ByteWriter out = CredentialCodec.exact(size);
        head(out, HELLO, counter);
        out.u8(credential.length);
        out.bytes(credential);
        out.u8(recipient.length);
        out.bytes(recipient);
        out.bytes(ephemeral);
        out.bytes(echo == null ? new byte[Ephemeral.BYTES] : echo);
        return out.array();
    }

    /**
     * A PAIR_MAC, TEAM_MAC or TEAM_KEY datagram: header, then {@code body}, then {@code tagBytes} of
     * room for the MAC ({@code body} of a TEAM_KEY is the sealed key, tag included, so 0 more).
     */
    static byte[] keyed(int kind, int teamId, byte[] sender, long counter, byte[] body, int tagBytes) {
        ByteWriter out = CredentialCodec.exact(keyedHeaderBytes(kind, sender.length) + body.length + tagBytes);
        out.u8(VERSION);
        out.u8(kind);
        if (kind == TEAM_MAC) {
            out.i32(teamId);
        }
        out.u8(sender.length);
        out.bytes(sender);
        writeCounter(out, counter);
        out.bytes(body);
        return out.array();
    }

    /** The bytes before the body of a keyed kind: what a TEAM_KEY's seal takes as associated data. */
    static int keyedHeaderBytes(int kind, int senderBytes) {
        return HEAD + 1 + senderBytes + (kind == TEAM_MAC ? TEAM_ID_BYTES : 0);
    }

    private static void head(ByteWriter out, int kind, long counter) {
        out.u8(VERSION);
        out.u8(kind);
        writeCounter(out, counter);
    }

    private static void writeCounter(ByteWriter out, long counter) {
        out.u16((int) (counter >>> 32) & 0xFFFF);
        out.i32((int) counter);
    }

    private static long readCounterBits(ByteReader<Malformed> in) throws Malformed {
        long high = in.u16("counter");
        return high << 32 | in.i32("counter") & 0xFFFF_FFFFL;
    }

    /**
     * The counter whose low 48 bits are {@code low} nearest {@code reference} (a receiver's clock
     * shifted as a sender's counter is): the sender's counter, if it lies within 2^47 of it.
     */
    static long counterNear(long low, long reference) {
        long candidate = reference & ~COUNTER_MASK | low;
        long half = 1L << (COUNTER_BITS - 1);
        if (candidate - reference > half) {
            return candidate - (1L << COUNTER_BITS);
        }
        if (reference - candidate > half) {
            return candidate + (1L << COUNTER_BITS);
        }
        return candidate;
    }

    /** What a signature covers: the full {@code counter}, then {@code datagram[0, length)}. */
    static byte[] toBeSigned(long counter, byte[] datagram, int length) {
        byte[] data = new byte[Long.BYTES + length];
        ByteWriter.putI64(data, 0, counter);
        System.arraycopy(datagram, 0, data, Long.BYTES, length);
        return data;
    }

    /**
     * Parses a datagram, taking its counter to be the one nearest {@code referenceCounter} (the
     * receiver's clock shifted as a counter is; see {@link #counterNear}). Checks only the form
     * (lengths, limits, UTF-8); no key is used.
     *
     * @throws Malformed naming the kind, the field, its offset and the rule
     */
    static Frame read(byte[] datagram, long referenceCounter) throws Malformed {
        ByteReader<Malformed> head = Malformed.reader(datagram, 0, datagram.length, "datagram");
        int version = head.u8("version");
        if (version != VERSION) {
            throw head.error(WireProblem.MALFORMED, 0, "version", version + " is not a known version; this reader knows " + VERSION);
        }
        int kind = head.u8("kind");
        return switch (kind) {
            case SIGNED, HELLO -> readSigned(datagram, kind, referenceCounter);
            case PAIR_MAC, TEAM_MAC, TEAM_KEY -> readKeyed(datagram, kind, referenceCounter);
            default -> throw head.error(WireProblem.MALFORMED, 1, "kind", kind + " is not a known kind; they are 1 to 5");
        };
    }

    private static Frame readSigned(byte[] datagram, int kind, long referenceCounter) throws Malformed {
        String what = kindName(kind);
        int signedLength = datagram.length - SIG;
        if (signedLength < HEAD + 1) {
            throw new Malformed(what + ": " + datagram.length + " bytes is too short to hold a header and a signature");
        }
        ByteReader<Malformed> in = Malformed.reader(datagram, 2, signedLength, what);
        long counter = counterNear(readCounterBits(in), referenceCounter);
        int credentialLength = in.u8("credential length");
        int at = in.position();
        in.take(credentialLength, "credential");
        Credential credential;
        try {
            credential = CredentialCodec.decode(datagram, at, credentialLength);
        } catch (Malformed e) {
            throw new Malformed(what + ": " + e.getMessage());
        }
        if (kind == SIGNED) {
            return new Frame.Signed(credential, counter, datagram, in.position(), signedLength);
        }
        String recipient = WireNames.read(in, "recipient");
        byte[] ephemeral = in.bytes(Ephemeral.BYTES, "ephemeral key");
        byte[] echo = in.bytes(Ephemeral.BYTES, "echoed ephemeral key");
        if (in.remaining() != 0) {
            throw in.error(WireProblem.MALFORMED, in.offset(), "signature", "found " + (in.remaining() + SIG) + " bytes; it is " + SIG);
        }
        return new Frame.Hello(credential, counter, recipient, ephemeral, echo, datagram, signedLength);
    }

    private static Frame readKeyed(byte[] datagram, int kind, long referenceCounter) throws Malformed {
        String what = kindName(kind);
        ByteReader<Malformed> in = Malformed.reader(datagram, 2, datagram.length, what);
        int teamId = kind == TEAM_MAC ? in.i32("team key id") : 0;
        String sender = WireNames.read(in, "sender");
        long counter = counterNear(readCounterBits(in), referenceCounter);
        int bodyStart = in.position();
        int bodyEnd;
        if (kind == TEAM_KEY) {
            bodyEnd = bodyStart + TEAM_KEY_BYTES + GCM_TAG_BYTES;
            if (datagram.length != bodyEnd) {
                throw in.error(WireProblem.MALFORMED, in.offset(), "sealed team key", "found " + in.remaining() + " bytes; it is "
                        + (TEAM_KEY_BYTES + GCM_TAG_BYTES));
            }
        } else {
            bodyEnd = datagram.length - MAC;
            if (bodyEnd < bodyStart) {
                throw in.error(WireProblem.TRUNCATED, in.offset(), "MAC", "truncated: needs " + MAC + " bytes, " + in.remaining() + " left");
            }
        }
        return new Frame.Keyed(kind, teamId, sender, counter, datagram, bodyStart, bodyEnd);
    }
}
