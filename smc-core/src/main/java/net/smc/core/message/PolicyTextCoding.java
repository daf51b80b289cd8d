package net.smc.core.message;

import java.util.Locale;
import java.util.zip.DataFormatException;
import java.util.zip.Deflater;
import java.util.zip.Inflater;

import net.smc.core.wire.ByteWriter;

/**
 * The wire form of a policy text ({@link PolicyReply#text()}): its length in UTF-8 bytes, a coding
 * byte, and either the text itself ({@link WireFormat#POLICY_TEXT_PLAIN}) or a zlib stream of it
 * (RFC 1950: DEFLATE behind a 2-byte header, with an Adler-32 checksum of the text) behind its own
 * two-byte length: deflated over the preset dictionary of PonderTalk phrases
 * ({@link WireFormat#POLICY_TEXT_DEFLATE_DICTIONARY}, {@link PolicyDictionary}), or without one
 * ({@link WireFormat#POLICY_TEXT_DEFLATE}). The encoder deflates a text of
 * {@link WireFormat#MIN_DEFLATED_POLICY_TEXT} bytes or more over the dictionary and keeps the
 * deflated form when it is shorter on the wire than the text. Policy files are small, repetitive
 * PonderTalk: a generated role's files shrink to about a sixth of their text over the dictionary
 * (two fifths without it), the reconnaissance mission's to about three tenths; everything above
 * the codec sees the text only.
 *
 * <p>Inflation is bounded: the declared length is checked against
 * {@link WireFormat#MAX_POLICY_TEXT} before anything is allocated, the stream is inflated into an
 * array of exactly that length (a stream that would give more is refused without producing it),
 * and it must end exactly there, using every byte it came with, its checksum right: a corrupted
 * stream is refused rather than read as another text. A stream of coding 2 must name the
 * dictionary (its DICTID), one of coding 1 must name none.
 *
 * <p>A text has more than one valid wire form (plain, or any DEFLATE stream of it); the decoder
 * accepts any, and the encoder always writes the same one for the same text.
 *
 * <p>The zlib state (about 300 KB for a deflater) is kept one per thread, not one per cell: a
 * cell's codec runs on its thread, and a simulation of thousands of cells on a few threads would
 * otherwise hold thousands of them.
 */
final class PolicyTextCoding {
    /** DEFLATE's level: 6, zlib's default; higher levels gain nothing on policy files (measured: the same bytes). */
    private static final int LEVEL = 6;

    private static final ThreadLocal<Deflater> DEFLATERS = ThreadLocal.withInitial(() -> new Deflater(LEVEL));
    private static final ThreadLocal<Inflater> INFLATERS = ThreadLocal.withInitial(() -> new Inflater());

    private PolicyTextCoding() {
    }

    /** Writes {@code text} (a valid policy text: well formed, at most {@link WireFormat#MAX_POLICY_TEXT} bytes). */
    static void write(String text, ByteWriter w) {
        int n = Utf8.length(text);
        byte[] utf8 = new byte[n];
        Utf8.encode(text, utf8, 0);
        w.u16(n);
        if (n >= WireFormat.MIN_DEFLATED_POLICY_TEXT) {
            byte[] deflated = new byte[n - 2]; // shorter on the wire than the text, its own length included
            int m = deflate(utf8, deflated);
            if (m >= 0) {
                w.u8(WireFormat.POLICY_TEXT_DEFLATE_DICTIONARY);
                w.u16(m);
                w.bytes(deflated, 0, m);
                return;
            }
        }
        w.u8(WireFormat.POLICY_TEXT_PLAIN);
        w.bytes(utf8);
    }

    /** Deflates {@code in} over the dictionary into {@code out}; the stream's length, or -1 if it does not fit in {@code out}. */
    private static int deflate(byte[] in, byte[] out) {
        Deflater d = DEFLATERS.get();
        d.reset();
        d.setDictionary(PolicyDictionary.BYTES);
        d.setInput(in);
        d.finish();
        int m = d.deflate(out, 0, out.length);
        return d.finished() ? m : -1;
    }

    /** Reads a policy text written by {@link #write}; errors name {@code field} and the rule broken. */
    static String read(DatagramReader r, String field) throws DecodeException {
        int n = r.u16("the length of " + field);
        if (n > WireFormat.MAX_POLICY_TEXT) {
            throw new DecodeException(RejectReason.OVERSIZED, field + " is " + n + " bytes; at most "
                    + WireFormat.MAX_POLICY_TEXT + " are allowed");
        }
        int coding = r.u8("the coding of " + field);
        if (coding == WireFormat.POLICY_TEXT_PLAIN) {
            return text(r.array(), r.take(n, field), n, field);
        }
        if (coding != WireFormat.POLICY_TEXT_DEFLATE && coding != WireFormat.POLICY_TEXT_DEFLATE_DICTIONARY) {
            throw new DecodeException(RejectReason.MALFORMED, "the coding of " + field + " is " + coding
                    + "; it is " + WireFormat.POLICY_TEXT_PLAIN + " (plain), " + WireFormat.POLICY_TEXT_DEFLATE
                    + " (DEFLATE) or " + WireFormat.POLICY_TEXT_DEFLATE_DICTIONARY + " (DEFLATE over the dictionary)");
        }
        int m = r.length16("the deflated " + field);
        int at = r.take(m, "the deflated " + field);
        byte[] utf8 = new byte[n];
        inflate(r.array(), at, m, utf8, coding == WireFormat.POLICY_TEXT_DEFLATE_DICTIONARY, field);
        return text(utf8, 0, n, field);
    }

    /**
     * Inflates exactly {@code out.length} bytes from {@code in[at, at+m)}: the stream must end there
     * and use all of its bytes, and name the dictionary if {@code dictionary}, else none.
     */
    private static void inflate(byte[] in, int at, int m, byte[] out, boolean dictionary, String field)
            throws DecodeException {
        Inflater inf = INFLATERS.get();
        inf.reset();
        inf.setInput(in, at, m);
        int got;
        try {
            got = inf.inflate(out);
            if (got == 0 && inf.needsDictionary()) {
                if (!dictionary) {
                    throw new DecodeException(RejectReason.MALFORMED, field + " is a DEFLATE stream that needs a"
                            + " preset dictionary; its coding (" + WireFormat.POLICY_TEXT_DEFLATE + ") uses none");
                }
                if (inf.getAdler() != (PolicyDictionary.ID & 0xFFFF_FFFFL)) {
                    throw new DecodeException(RejectReason.MALFORMED, String.format(Locale.ROOT,
                            "%s is a DEFLATE stream over the dictionary %08x; this format's is %08x", field,
                            inf.getAdler(), PolicyDictionary.ID));
                }
                inf.setDictionary(PolicyDictionary.BYTES);
                got = inf.inflate(out);
            } else if (dictionary && (got > 0 || inf.finished())) {
                throw new DecodeException(RejectReason.MALFORMED, field + " is a DEFLATE stream that names no"
                        + " preset dictionary; its coding (" + WireFormat.POLICY_TEXT_DEFLATE_DICTIONARY
                        + ") uses the dictionary of PonderTalk phrases");
            }
            if (got == out.length && !inf.finished() && inf.inflate(new byte[1]) > 0) {
                throw new DecodeException(RejectReason.OVERSIZED, field + " inflates to more than the "
                        + out.length + " bytes it declares");
            }
        } catch (DataFormatException e) {
            throw new DecodeException(RejectReason.MALFORMED, field + " is not a valid DEFLATE stream ("
                    + e.getMessage() + ")");
        }
        if (!inf.finished()) {
            throw new DecodeException(RejectReason.TRUNCATED, "the DEFLATE stream of " + field + " ends after "
                    + got + " of the " + out.length + " bytes it declares");
        }
        if (got != out.length) {
            throw new DecodeException(RejectReason.MALFORMED, field + " inflates to " + got + " bytes, not the "
                    + out.length + " it declares");
        }
        if (inf.getRemaining() != 0) {
            throw new DecodeException(RejectReason.MALFORMED, inf.getRemaining() + " bytes follow the DEFLATE"
                    + " stream of " + field);
        }
    }

    private static String text(byte[] b, int at, int n, String field) throws DecodeException {
        if (!Utf8.isWellFormed(b, at, n)) {
            throw new DecodeException(RejectReason.MALFORMED, field + " is not well-formed UTF-8");
        }
        return Utf8.decode(b, at, n);
    }
}
