package net.smc.scenario.netns;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * The machine's network namespaces as the lab sees them: listing them, and removing some for good,
 * processes first (a namespace outlives {@code ip netns delete} while a process is inside it).
 * Problems are collected rather than thrown, so that one failure does not stop the rest of a cleanup.
 */
final class Namespaces {
    /** How long killed processes get to end, all together. */
    static final Duration KILL_WAIT = Duration.ofSeconds(10);

    private Namespaces() {
    }

    /** The names of every network namespace of the machine ({@code ip netns list}). */
    static List<String> names(Path ip) throws IOException {
        List<String> names = new ArrayList<>();
        for (String line : Exec.check(List.of(ip.toString(), "netns", "list")).split("\n")) {
            String name = line.strip().split("\\s+")[0];   // "name (id: 3)"
            if (!name.isEmpty()) {
                names.add(name);
            }
        }
        return names;
    }

    /**
     * Kills {@code processes} and every process inside {@code namespaces} with SIGKILL, waits for
     * them to end, then deletes the namespaces in reverse order (which removes their links).
     *
     * @param problems where what could not be done is added, one message each
     */
    static void remove(Path ip, List<String> namespaces, Collection<ProcessHandle> processes, List<String> problems) {
        List<ProcessHandle> killed = new ArrayList<>(processes);
        for (String namespace : namespaces) {
            try {
                killed.addAll(processesIn(ip, namespace));
            } catch (IOException e) {
                problems.add(e.getMessage());
            }
        }
        killed.forEach(ProcessHandle::destroyForcibly);
        awaitEnd(killed, problems);
        for (int i = namespaces.size() - 1; i >= 0; i--) {
            try {
                Exec.Result result = Exec.run(List.of(ip.toString(), "netns", "delete", namespaces.get(i)));
                if (!result.ok()) {
                    problems.add(result.failure());
                }
            } catch (IOException e) {
                problems.add(e.getMessage());
            }
        }
    }

    /** The processes inside {@code namespace} ({@code ip netns pids}). */
    private static List<ProcessHandle> processesIn(Path ip, String namespace) throws IOException {
        List<ProcessHandle> found = new ArrayList<>();
        for (String pid : Exec.check(List.of(ip.toString(), "netns", "pids", namespace)).split("\\s+")) {
            if (!pid.isEmpty()) {
                ProcessHandle.of(Long.parseLong(pid)).ifPresent(found::add);
            }
        }
        return found;
    }

    /** Waits for killed processes to end; one that will not is a problem to report. */
    private static void awaitEnd(List<ProcessHandle> killed, List<String> problems) {
        long deadline = System.nanoTime() + KILL_WAIT.toNanos();
        for (ProcessHandle handle : killed) {
            try {
                handle.onExit().get(Math.max(deadline - System.nanoTime(), 0), TimeUnit.NANOSECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                problems.add("interrupted while waiting for process " + handle.pid() + " to end");
                return;
            } catch (ExecutionException | TimeoutException e) {
                problems.add("process " + handle.pid() + " did not end within " + KILL_WAIT.toSeconds() + " s of SIGKILL");
            }
        }
    }
}
