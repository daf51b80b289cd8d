package net.smc.demo;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;

/** The folder a command's {@code --out} names: made if missing, a usage error naming it if it cannot be. */
final class OutFolder {
    private OutFolder() {
    }

    /**
     * {@code out} resolved against {@code workingDir}, made (with its parents) if missing.
     *
     * @throws ParameterException if a file of that name is there, or the folder cannot be made
     */
    static Path make(CommandSpec spec, Path workingDir, Object out) {
        Path target = workingDir.resolve(out.toString());
        if (Files.exists(target) && !Files.isDirectory(target)) {
            throw new ParameterException(spec.commandLine(), "--out '" + out + "': not a directory (a file of that name is there)");
        }
        try {
            return Files.createDirectories(target);
        } catch (IOException e) {
            throw new ParameterException(spec.commandLine(), "--out '" + out + "': cannot create the directory: "
                    + e.getClass().getSimpleName() + " " + e.getMessage());
        }
    }
}
