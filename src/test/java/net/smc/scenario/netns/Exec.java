package net.smc.scenario.netns;

import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * Runs the short system commands of the lab ({@code ip}, {@code nft}, {@code iptables},
 * {@code apt-get}) and finds them. Output (stdout and stderr together) goes through a temporary
 * file, so a command that leaves a child holding its output open cannot hang the caller; a
 * command that outlives its timeout is killed.
 */
final class Exec {
    /** Long enough for any {@code ip}, {@code nft} or {@code iptables} call, even on a busy machine. */
    static final Duration TIMEOUT = Duration.ofSeconds(30);
    /** Where root's tools live even when the JVM's PATH lacks the sbin folders. */
    private static final List<String> EXTRA_DIRS = List.of("/usr/local/sbin", "/usr/sbin", "/sbin");

    private Exec() {
    }

    /** A finished command: its exit status and what it printed. */
    record Result(List<String> command, int status, String output) {
        boolean ok() {
            return status == 0;
        }

        /** "`cmd args` failed with exit status N: output", for errors. */
        String failure() {
            return "`" + String.join(" ", command) + "` failed with exit status " + status
                    + (output.isBlank() ? "" : ": " + output.strip());
        }
    }

    /** The executable {@code tool} on the PATH or in the sbin folders. */
    static Optional<Path> find(String tool) {
        List<String> dirs = new ArrayList<>();
        String path = System.getenv("PATH");
        if (path != null) {
            dirs.addAll(List.of(path.split(File.pathSeparator)));
        }
        dirs.addAll(EXTRA_DIRS);
        return dirs.stream()
                .filter(dir -> !dir.isEmpty())
                .map(dir -> Path.of(dir, tool))
                .filter(Files::isExecutable)
                .findFirst();
    }

    /** Runs {@code command} with no input and {@link #TIMEOUT}. */
    static Result run(List<String> command) throws IOException {
        return run(command, null, Map.of(), TIMEOUT);
    }

    /**
     * Runs {@code command}, writes {@code stdin} (when not null) to it, and waits up to {@code timeout}.
     *
     * @throws IOException when it cannot start, or does not end in time (it is killed then)
     */
    static Result run(List<String> command, String stdin, Map<String, String> environment, Duration timeout)
            throws IOException {
        Path output = Files.createTempFile("smc-netns-exec", ".log");
        try {
            ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(output.toFile());
            builder.environment().putAll(environment);
            if (stdin == null) {
                builder.redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
            }
            Process process = builder.start();
            if (stdin != null) {
                try (OutputStream in = process.getOutputStream()) {
                    in.write(stdin.getBytes(StandardCharsets.UTF_8));
                }
            }
            if (!process.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS)) {
                process.destroyForcibly();
                throw new IOException("`" + String.join(" ", command) + "` did not end within " + timeout.toSeconds()
                        + " s; it was killed");
            }
            return new Result(List.copyOf(command), process.exitValue(), Files.readString(output));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while waiting for `" + String.join(" ", command) + "`", e);
        } finally {
            Files.deleteIfExists(output);
        }
    }

    /**
     * Runs {@code command} and returns its output.
     *
     * @throws IOException naming the command, its exit status and its output when it fails
     */
    static String check(List<String> command) throws IOException {
        return check(command, null);
    }

    /** Runs {@code command} with {@code stdin} as its input and returns its output; throws as {@link #check(List)}. */
    static String check(List<String> command, String stdin) throws IOException {
        Result result = run(command, stdin, Map.of(), TIMEOUT);
        if (!result.ok()) {
            throw new IOException(result.failure());
        }
        return result.output();
    }
}
