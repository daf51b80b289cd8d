package net.smc.sim.experiment;

import java.nio.file.Files;
import java.nio.file.Path;

/** Finds the project's files from a test's working directory (the module's or the project's). */
final class Project {
    private Project() {
    }

    static Path bootEvents() {
        for (String dir : new String[] {"..", "."}) {
            Path p = Path.of(dir, "policies", "boot", "events.p2");
            if (Files.isRegularFile(p)) {
                return p;
            }
        }
        throw new IllegalStateException("policies/boot/events.p2 not found from " + Path.of("").toAbsolutePath());
    }
}
