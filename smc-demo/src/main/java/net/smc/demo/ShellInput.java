package net.smc.demo;

import java.io.BufferedInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;

/**
 * Splits the shell's standard input into inputs. An input ends at a line whose last character,
 * after trailing whitespace, is {@code .}; the tokens are not looked at, so a line that ends with
 * {@code .} inside a string literal or a comment also ends the input. Blank lines before an input
 * are skipped; text left at the end of the stream without a final {@code .} is one last input.
 * On a terminal, prompts {@code smc> } for an input's first line and {@code ...> } for the rest;
 * there the lines come from {@link TerminalLines} (line editing and history), elsewhere from the
 * stream as they are.
 */
final class ShellInput {
    static final String PROMPT = "smc> ";
    static final String CONTINUATION = "...> ";

    /** Where the lines come from: a pipe or file, or a terminal's line editor. */
    interface LineSource {
        /** The next line without its ending, after showing {@code prompt} if it shows prompts; null at the end. */
        String readLine(String prompt) throws IOException;

        /** Shows that the input ended (a terminal moves to a fresh line). */
        default void ended() {
        }
    }

    private final LineSource lines;

    ShellInput(Io io) {
        this(piped(io));
    }

    ShellInput(LineSource lines) {
        this.lines = lines;
    }

    /**
     * Lines read from {@code io}'s stdin as UTF-8; prompts go to its stdout when it is interactive.
     * A line that is not valid UTF-8 is refused ({@link MalformedLine}, naming its line and first
     * bad byte), as the files of {@code smc run} are.
     */
    static LineSource piped(Io io) {
        InputStream in = new BufferedInputStream(io.stdin());
        PrintWriter prompts = io.interactive() ? io.stdout() : null;
        return new LineSource() {
            private int lineNumber;

            @Override
            public String readLine(String prompt) throws IOException {
                if (prompts != null) {
                    prompts.print(prompt);
                    prompts.flush();
                }
                byte[] line = rawLine(in);
                if (line == null) {
                    return null;
                }
                lineNumber++;
                int bad = firstBadByte(line);
                if (bad < 0) {
                    return new String(line, StandardCharsets.UTF_8);
                }
                throw new MalformedLine(ShellCommand.SOURCE + ":" + lineNumber + ": not valid UTF-8: byte 0x"
                        + String.format("%02X", line[bad] & 0xff) + " at byte " + (bad + 1)
                        + " of the line; the shell reads UTF-8, and skips the input the line belongs to");
            }

            @Override
            public void ended() {
                if (prompts != null) {
                    prompts.println();
                }
            }
        };
    }

    /** The bytes of the next line without its ending (a line feed, and a carriage return before it); null at the end. */
    private static byte[] rawLine(InputStream in) throws IOException {
        ByteArrayOutputStream line = new ByteArrayOutputStream();
        int b = in.read();
        if (b < 0) {
            return null;
        }
        while (b >= 0 && b != '\n') {
            line.write(b);
            b = in.read();
        }
        byte[] bytes = line.toByteArray();
        return bytes.length > 0 && bytes[bytes.length - 1] == '\r' ? java.util.Arrays.copyOf(bytes, bytes.length - 1) : bytes;
    }

    /** The index of the first byte of {@code line} that is not part of a well-formed UTF-8 character, or -1. */
    private static int firstBadByte(byte[] line) {
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer bytes = ByteBuffer.wrap(line);
        CoderResult result = decoder.decode(bytes, CharBuffer.allocate(line.length + 1), true);
        return result.isError() ? bytes.position() : -1;
    }

    /** A line of input that cannot be read as text; its message names the line and why. */
    static final class MalformedLine extends IOException {
        private static final long serialVersionUID = 1L;

        MalformedLine(String message) {
            super(message);
        }
    }

    /**
     * The next input's text (its lines, each ending in a newline), or {@code null} at the end. An
     * input with a line that cannot be read ({@link MalformedLine}) is skipped whole, up to its last
     * line, and {@code refused} told why: run without that line it would be another statement.
     */
    String next(java.util.function.Consumer<String> refused) throws IOException {
        StringBuilder text = new StringBuilder();
        boolean skipping = false;
        while (true) {
            String line;
            try {
                line = lines.readLine(text.isEmpty() && !skipping ? PROMPT : CONTINUATION);
            } catch (MalformedLine bad) {
                refused.accept(bad.getMessage());
                skipping = true;
                text.setLength(0);
                continue;
            }
            if (line == null) {
                lines.ended();
                return text.isEmpty() || skipping ? null : text.toString();
            }
            if (skipping) {
                if (line.stripTrailing().endsWith(".")) {
                    skipping = false;   // the refused input ends here; the next one starts after it
                }
                continue;
            }
            if (text.isEmpty() && line.isBlank()) {
                continue;
            }
            text.append(line).append('\n');
            if (line.stripTrailing().endsWith(".")) {
                return text.toString();
            }
        }
    }
}
