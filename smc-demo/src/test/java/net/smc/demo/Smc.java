package net.smc.demo;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Runs the {@code smc} command in-process, as {@link Main#main} would but on given stdin and
 * working directory, and captures what it writes.
 *
 * @param workingDir  the command's current directory (relative file names resolve against it)
 * @param interactive whether the command is told that stdin is a terminal
 */
record Smc(Path workingDir, boolean interactive) {

    static Smc in(Path workingDir) {
        return new Smc(workingDir, false);
    }

    Smc onTerminal() {
        return new Smc(workingDir, true);
    }

    /** Runs with empty stdin. */
    Result run(String... args) {
        return withInput("", args);
    }

    Result withInput(String stdin, String... args) {
        return withInputBytes(stdin.getBytes(StandardCharsets.UTF_8), args);
    }

    /** Runs with {@code stdin} as raw bytes (which need not be UTF-8). */
    Result withInputBytes(byte[] stdin, String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        Io io = new Io(new ByteArrayInputStream(stdin),
                new PrintWriter(out, true), new PrintWriter(err, true), interactive, workingDir);
        int status = Main.commandLine(io).execute(args);
        return new Result(status, out.toString(), err.toString());
    }

    /**
     * Writes a file under the working directory and answers its absolute path, which is also how
     * diagnostics name it when it is given to the command.
     */
    String file(String name, String text) {
        Path file = workingDir.resolve(name);
        try {
            Files.writeString(file, text);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return file.toString();
    }

    record Result(int status, String out, String err) {
        List<String> outLines() {
            return out.lines().toList();
        }

        List<String> errLines() {
            return err.lines().toList();
        }
    }
}
