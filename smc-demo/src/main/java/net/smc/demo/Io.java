package net.smc.demo;

import java.io.InputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/**
 * The outside world of one {@code smc} invocation, injected so that tests can run the commands
 * in-process.
 *
 * @param stdin       where the shell reads its inputs
 * @param stdout      {@code root print:} lines and shell values
 * @param stderr      diagnostics and usage errors
 * @param interactive whether stdin is a terminal (the shell then prints prompts)
 * @param workingDir  the current directory: relative file names and the default {@code policies/}
 *                    repository resolve against it
 */
record Io(InputStream stdin, PrintWriter stdout, PrintWriter stderr, boolean interactive, Path workingDir) {

    /** The process's own streams (UTF-8, flushed at every line) and current directory. */
    static Io system() {
        return new Io(System.in,
                new PrintWriter(new OutputStreamWriter(System.out, StandardCharsets.UTF_8), true),
                new PrintWriter(new OutputStreamWriter(System.err, StandardCharsets.UTF_8), true),
                System.console() != null,
                Path.of(""));
    }
}
