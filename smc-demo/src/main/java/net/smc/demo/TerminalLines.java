package net.smc.demo;

import java.io.Closeable;
import java.io.IOException;
import java.nio.file.Path;
import org.jline.reader.EndOfFileException;
import org.jline.reader.LineReader;
import org.jline.reader.LineReaderBuilder;
import org.jline.reader.UserInterruptException;
import org.jline.terminal.Terminal;
import org.jline.terminal.TerminalBuilder;

/**
 * The shell's lines on a terminal, through JLine: prompts, line editing, and a history kept in
 * {@code ~/.smc_history} (Up/Down, Ctrl-R). Ctrl-D on an empty line ends the input; Ctrl-C drops
 * the line being edited. Each line of an unfinished input is its own history entry.
 */
final class TerminalLines implements ShellInput.LineSource, Closeable {
    private final Terminal terminal;
    private final LineReader reader;

    private TerminalLines(Terminal terminal, LineReader reader) {
        this.terminal = terminal;
        this.reader = reader;
    }

    /** The process's terminal, with history in {@code history}. */
    static TerminalLines open(Path history) throws IOException {
        Terminal terminal = TerminalBuilder.builder().system(true).name("smc").build();
        LineReader reader = LineReaderBuilder.builder().terminal(terminal).appName("smc")
                .variable(LineReader.HISTORY_FILE, history)
                .option(LineReader.Option.DISABLE_EVENT_EXPANSION, true)
                .build();
        return new TerminalLines(terminal, reader);
    }

    @Override
    public String readLine(String prompt) {
        while (true) {
            try {
                return reader.readLine(prompt);
            } catch (UserInterruptException dropped) {
                // Ctrl-C: the line is dropped; ask again
            } catch (EndOfFileException end) {
                return null;
            }
        }
    }

    @Override
    public void ended() {
        terminal.writer().println();
        terminal.flush();
    }

    @Override
    public void close() throws IOException {
        try {
            reader.getHistory().save();
        } finally {
            terminal.close();
        }
    }
}
