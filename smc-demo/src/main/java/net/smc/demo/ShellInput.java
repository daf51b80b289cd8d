package net.smc.demo;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
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

    /** Lines read from {@code io}'s stdin; prompts go to its stdout when it is interactive. */
    static LineSource piped(Io io) {
        BufferedReader reader = new BufferedReader(new InputStreamReader(io.stdin(), StandardCharsets.UTF_8));
        PrintWriter prompts = io.interactive() ? io.stdout() : null;
        return new LineSource() {
            @Override
            public String readLine(String prompt) throws IOException {
                if (prompts != null) {
                    prompts.print(prompt);
                    prompts.flush();
                }
                return reader.readLine();
            }

            @Override
            public void ended() {
                if (prompts != null) {
                    prompts.println();
                }
            }
        };
    }

    /** The next input's text (its lines, each ending in a newline), or {@code null} at the end. */
    String next() throws IOException {
        StringBuilder text = new StringBuilder();
        while (true) {
            String line = lines.readLine(text.isEmpty() ? PROMPT : CONTINUATION);
            if (line == null) {
                lines.ended();
                return text.isEmpty() ? null : text.toString();
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
