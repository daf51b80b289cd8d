package net.smc.demo;

import java.nio.file.Path;
import java.util.List;
import java.util.OptionalInt;
import java.util.Random;
import net.smc.policy.api.AuthMode;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.PolicyRepository;
import net.smc.policy.RunResult;

/**
 * One fresh cell as the {@code smc} command runs it: {@code root print:} lines go to stdout,
 * diagnostics to stderr as {@code FILE:LINE:COL: message}, and every diagnostic is counted (errors
 * inside policies included, though they do not make a unit fail). The clock is the system clock
 * and the random source unseeded.
 */
final class CommandCell {
    private final PolicyEngine cell;
    private int diagnostics;
    private int failedUnits;

    CommandCell(Io io, AuthMode auth, PolicyRepository repository, List<String> userArguments) {
        this.cell = PolicyEngine.builder()
                .output(io.stdout()::println)
                .errors(d -> {
                    diagnostics++;
                    io.stderr().println(d);
                })
                .auth(auth)
                .clock(System::currentTimeMillis)
                .random(new Random())
                .repository(repository)
                .arguments(userArguments)
                .build();
    }

    /**
     * Runs the files in order as boot units; a unit's error does not stop the later files, but
     * {@code root exit} stops everything. Does not end the boot phase.
     */
    void boot(List<Path> files) {
        for (Path file : files) {
            RunResult result = cell.runFile(file);
            if (cell.exitStatus().isPresent()) {
                return;
            }
            if (!result.ok()) {
                failedUnits++;
            }
        }
    }

    /**
     * Runs the cell's timers on the system clock until none is pending (every ticker stopped or
     * cancelled, every one-shot fired), {@code root exit} ran, or {@code stop} fired: the process
     * waits between them.
     */
    void runTimers(StopSignal stop) throws InterruptedException {
        var timers = cell.timers();
        while (cell.exitStatus().isEmpty() && timers.nextDue().isPresent()) {
            long wait = timers.nextDue().getAsLong() - System.currentTimeMillis();
            if (wait > 0 && stop.await(wait)) {
                return;
            }
            timers.runDue();
        }
    }

    PolicyEngine cell() {
        return cell;
    }

    /** The status {@code root exit} gave, once it ran. */
    OptionalInt exitStatus() {
        return cell.exitStatus();
    }

    /** Whether no unit failed and no diagnostic at all was reported. */
    boolean clean() {
        return failedUnits == 0 && diagnostics == 0;
    }
}
