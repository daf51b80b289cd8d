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
 * On a terminal, prompts {@code smc> } for an input's first line and {@code ...> } for the rest.
 */
final class ShellInput {
    static final String PROMPT = "smc> ";
    static final String CONTINUATION = "...> ";

    private final BufferedReader reader;
    /** Where prompts go; {@code null} when stdin is not a terminal. */
    private final PrintWriter prompts;

    ShellInput(Io io) {
        this.reader = new BufferedReader(new InputStreamReader(io.stdin(), StandardCharsets.UTF_8));
        this.prompts = io.interactive() ? io.stdout() : null;
    }

    /** The next input's text (its lines, each ending in a newline), or {@code null} at the end. */
    String next() throws IOException {
        StringBuilder text = new StringBuilder();
        while (true) {
            prompt(text.isEmpty() ? PROMPT : CONTINUATION);
            String line = reader.readLine();
            if (line == null) {
                if (prompts != null) {
                    prompts.println();
                }
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

    private void prompt(String prompt) {
        if (prompts != null) {
            prompts.print(prompt);
            prompts.flush();
        }
    }
}
