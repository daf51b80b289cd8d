package net.smc.policy.lang;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.Charset;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Reads PonderTalk source files: UTF-8 (a leading byte-order mark is skipped), or UTF-16 when the
 * file starts with a UTF-16 byte-order mark. Bytes that are not valid in that encoding are refused
 * with the byte offset and line of the first one; a file too large for a unit is refused before it
 * is read. The text is decoded straight into its string (one copy beside the file's bytes).
 */
public final class SourceFiles {
    private SourceFiles() {
    }

    /**
     * The text of {@code file}.
     *
     * @param maxChars the most characters a unit may have; a file with more bytes than a unit of
     *                 that many characters can take in any supported encoding is refused unread
     * @throws IOException with a message naming the problem (not the file: the caller does)
     */
    public static String read(Path file, int maxChars) throws IOException {
        long size = Files.size(file);
        if (size > 4L * maxChars + 4) {
            throw new IOException("file of " + size + " bytes is larger than a unit may be (at most "
                    + maxChars + " characters)");
        }
        return decode(Files.readAllBytes(file));
    }

    /** Decodes a source file's bytes (see the class comment). */
    public static String decode(byte[] bytes) throws CharacterCodingException {
        Charset charset = StandardCharsets.UTF_8;
        int skip = 0;
        if (bytes.length >= 3 && (bytes[0] & 0xff) == 0xEF && (bytes[1] & 0xff) == 0xBB && (bytes[2] & 0xff) == 0xBF) {
            skip = 3;
        } else if (bytes.length >= 2 && (bytes[0] & 0xff) == 0xFE && (bytes[1] & 0xff) == 0xFF) {
            charset = StandardCharsets.UTF_16BE;
            skip = 2;
        } else if (bytes.length >= 2 && (bytes[0] & 0xff) == 0xFF && (bytes[1] & 0xff) == 0xFE) {
            charset = StandardCharsets.UTF_16LE;
            skip = 2;
        }
        String text = new String(bytes, skip, bytes.length - skip, charset);
        if (text.indexOf('\uFFFD') >= 0) {
            checkStrictly(bytes, skip, charset);
        }
        return text;
    }

    /**
     * Decodes again, strictly, when the lenient decoding put in a replacement character: either
     * the bytes are invalid (refused, naming the first bad byte) or the text holds U+FFFD itself.
     * Decodes in small pieces, so a large file is not copied again.
     */
    private static void checkStrictly(byte[] bytes, int skip, Charset charset) throws CharacterCodingException {
        CharsetDecoder decoder = charset.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes, skip, bytes.length - skip);
        CharBuffer out = CharBuffer.allocate(8192);
        CoderResult result;
        do {
            out.clear();
            result = decoder.decode(in, out, true);
        } while (result.isOverflow());
        if (!result.isError()) {
            do {
                out.clear();
                result = decoder.flush(out);
            } while (result.isOverflow());
        }
        if (result.isError()) {
            int at = in.position();
            String message = "not valid " + charset.name() + ": byte 0x" + String.format("%02X", bytes[at] & 0xff)
                    + " at byte offset " + at + " (line " + lineOf(bytes, at) + ") "
                    + (result.isMalformed() ? "is not part of a well-formed character" : "cannot be mapped")
                    + "; save the file as UTF-8 (or as UTF-16 with a byte-order mark)";
            throw new CharacterCodingException() {
                @Override
                public String getMessage() {
                    return message;
                }
            };
        }
    }

    /** The line of a byte: lines end at a line feed, or a carriage return that no line feed follows (as the lexer counts them). */
    private static int lineOf(byte[] bytes, int offset) {
        int line = 1;
        for (int i = 0; i < offset; i++) {
            if (bytes[i] == '\n' || bytes[i] == '\r' && (i + 1 >= bytes.length || bytes[i + 1] != '\n')) {
                line++;
            }
        }
        return line;
    }
}
