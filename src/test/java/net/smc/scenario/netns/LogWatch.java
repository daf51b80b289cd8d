package net.smc.scenario.netns;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * Waits for a line in the log of a process the lab started: how a test learns that a process in
 * another namespace is ready, or what it saw. Polls the file every {@value #POLL_MILLIS} ms, which
 * is all a test can do with a process it only shares a file with.
 */
public final class LogWatch {
    static final long POLL_MILLIS = 20;
    private static final int TAIL_LINES = 20;

    private LogWatch() {
    }

    /**
     * The first line of {@code log} that {@code match} accepts, once there is one.
     *
     * @param what what is awaited, for the failure message (e.g. "the listener on host 1 is ready")
     * @throws AssertionError naming the log, what was awaited and the log's last lines, when no line
     *                        matches within {@code timeout}
     */
    public static String await(Path log, String what, Predicate<String> match, Duration timeout)
            throws IOException, InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            Optional<String> found = lines(log).stream().filter(match).findFirst();
            if (found.isPresent()) {
                return found.get();
            }
            if (System.nanoTime() > deadline) {
                List<String> lines = lines(log);
                throw new AssertionError("waited " + timeout.toMillis() + " ms for " + what + " in " + log
                        + "; its last lines: " + lines.subList(Math.max(0, lines.size() - TAIL_LINES), lines.size()));
            }
            Thread.sleep(POLL_MILLIS);
        }
    }

    /** The complete lines of {@code log} so far (a line still being written is left out); none when it does not exist yet. */
    public static List<String> lines(Path log) throws IOException {
        String text;
        try {
            text = new String(Files.readAllBytes(log), StandardCharsets.UTF_8);   // replaces a half-written character
        } catch (NoSuchFileException e) {
            return List.of();
        }
        int end = text.lastIndexOf('\n');
        return end < 0 ? List.of() : text.substring(0, end).lines().toList();
    }
}
