package net.smc.demo;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import net.smc.policy.api.AuthMode;
import net.smc.policy.api.PolicyRepository;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.TypeConversionException;

/**
 * The options {@code run} and {@code shell} share ({@code --auth}, {@code --repository}), and the
 * checks of their arguments that make a usage error (exit status 2) before anything runs.
 */
final class CellOptions {
    /** The repository used when {@code --repository} is not given, if the current directory has it. */
    static final String DEFAULT_REPOSITORY = "policies";
    /**
     * The exit status of a command stopped by a signal, as the shell shows one ended by SIGTERM
     * (128 + 15); the process itself exits with the JVM's status for the signal it got (130 for SIGINT).
     */
    static final int STOPPED = 143;

    @Option(names = "--auth", paramLabel = "allow|deny", converter = AuthConverter.class,
            description = "Check authorisation policies; when none decides, allow or deny. "
                    + "The files given run as boot units, during which the default is allow. "
                    + "Without this option nothing is checked.")
    AuthMode auth = AuthMode.OFF;

    @Option(names = "--repository", paramLabel = "DIR",
            description = "The policy repository that policy: URIs and includes resolve against "
                    + "(default: the " + DEFAULT_REPOSITORY + "/ folder of the current directory, if there is one).")
    Path repository;

    /** The user's arguments ({@code root argsAsArray}): for {@code smc run}, those after {@code --}. */
    List<String> userArguments = List.of();

    /** The policy repository to use, or {@code null} when there is none. */
    PolicyRepository repository(CommandSpec spec, Path workingDir) {
        if (repository == null) {
            Path fallback = workingDir.resolve(DEFAULT_REPOSITORY);
            return Files.isDirectory(fallback) ? new PolicyRepository(fallback) : null;
        }
        Path dir = workingDir.resolve(repository);
        if (!Files.isDirectory(dir)) {
            throw new ParameterException(spec.commandLine(), "--repository '" + repository + "': "
                    + (Files.exists(dir) ? "not a directory" : "no such directory"));
        }
        return new PolicyRepository(dir);
    }

    /**
     * The files resolved against the working directory, each checked to be a readable regular file.
     *
     * @throws ParameterException naming the first file that is not, and why
     */
    static List<Path> readableFiles(CommandSpec spec, Path workingDir, List<Path> files) {
        List<Path> resolved = new ArrayList<>();
        for (Path given : files) {
            if (given.toString().isEmpty()) {
                throw new ParameterException(spec.commandLine(), "a file name is empty; name the file to read");
            }
            Path file = workingDir.resolve(given);
            String problem = readProblem(file);
            if (problem != null) {
                throw new ParameterException(spec.commandLine(), "cannot read '" + given + "': " + problem);
            }
            resolved.add(file);
        }
        return resolved;
    }

    /** {@code allow} or {@code deny}, exactly. */
    /** What a command does with its cell once the boot files have run. */
    @FunctionalInterface
    interface BootedWork {
        int run(CommandCell cell) throws Exception;
    }

    /**
     * Checks the files and the repository (usage errors), then, on a large stack, boots the files
     * in one fresh cell, ends the boot phase and runs {@code work}; answers its exit status.
     */
    int withBootedCell(CommandSpec spec, Io io, List<Path> files, BootedWork work) throws Exception {
        return withBootedCell(spec, io, files, StopSignal.manual(), work);
    }

    /**
     * As {@link #withBootedCell(CommandSpec, Io, List, BootedWork)}, and when {@code stop} fires the
     * cell is stopped ({@link net.smc.policy.PolicyEngine#stop}, status {@value #STOPPED}) whatever it
     * is running, and the command ends with one line saying why.
     */
    int withBootedCell(CommandSpec spec, Io io, List<Path> files, StopSignal stop, BootedWork work) throws Exception {
        List<Path> units = readableFiles(spec, io.workingDir(), files);
        PolicyRepository repo = repository(spec, io.workingDir());
        try {
            return LargeStack.call(() -> {
                CommandCell cell = new CommandCell(io, auth, repo, userArguments);
                stop.whenTriggered(() -> cell.cell().stop(STOPPED));
                cell.boot(units);
                cell.cell().endBoot();
                return work.run(cell);
            });
        } catch (OutOfMemoryError e) {
            // The cell's thread has ended, so its objects are garbage by now and printing works.
            io.stderr().println(spec.qualifiedName() + ": out of memory (the Java heap is at most "
                    + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MB) while running " + files
                    + "; give the JVM more with JAVA_OPTS=-Xmx..., or use smaller files");
            io.stderr().flush();
            return 1;
        }
    }

    static final class AuthConverter implements ITypeConverter<AuthMode> {
        @Override
        public AuthMode convert(String value) {
            return switch (value) {
                case "allow" -> AuthMode.ALLOW;
                case "deny" -> AuthMode.DENY;
                default -> throw new TypeConversionException("'" + value + "' is neither 'allow' nor 'deny'");
            };
        }
    }

    /**
     * The folders of {@code --allow-path}, resolved against the working directory, each checked to be a folder.
     *
     * @throws ParameterException naming the first that is not
     */
    static List<Path> allowedFolders(CommandSpec spec, Path workingDir, List<Path> folders) {
        List<Path> resolved = new ArrayList<>();
        for (Path given : folders) {
            Path folder = workingDir.resolve(given);
            if (given.toString().isEmpty() || !Files.isDirectory(folder)) {
                throw new ParameterException(spec.commandLine(), "--allow-path '" + given + "': "
                        + (given.toString().isEmpty() ? "is empty" : Files.exists(folder) ? "not a folder" : "no such folder")
                        + "; it names a folder mission files may come from");
            }
            resolved.add(folder);
        }
        return resolved;
    }

    /** Why {@code file} cannot be read as a regular file, or null when it can. */
    static String readProblem(Path file) {
        return !Files.exists(file) ? "no such file"
                : Files.isDirectory(file) ? "is a directory"
                : !Files.isRegularFile(file) ? "not a regular file"
                : !Files.isReadable(file) ? "permission denied"
                : null;
    }
}
