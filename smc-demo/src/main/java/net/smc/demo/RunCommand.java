package net.smc.demo;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code smc run FILE.p2 ...}: runs the files in order, as boot units of one fresh cell. */
@Command(name = "run", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {
            "Runs PonderTalk files in order in one fresh cell, each file as one boot unit.",
            "root print: lines go to standard output, one line per print and nothing else. "
                    + "Errors go to standard error as FILE:LINE:COL: message. "
                    + "A unit with an error stops there; the later files still run."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:every unit ran and no error was reported",
            "1:an error was reported: a syntax or runtime error in a unit, or an error inside a policy "
                    + "(which does not stop the unit, but counts)",
            "2:usage error: unknown option, bad --auth value, no files, a file that cannot be read",
            "130, 143:ended by SIGINT (Ctrl-C) or SIGTERM, whatever it was running, with one line saying so",
            "n:a unit ran root exit: n (root exit is 0); the later files do not run"})
final class RunCommand implements Callable<Integer> {
    private final Io io;
    private final Supplier<StopSignal> stops;

    @Spec
    CommandSpec spec;

    @Mixin
    CellOptions options;

    @Parameters(arity = "1..*", paramLabel = "FILE.p2", description = {"The files to run, in order.",
        "Arguments after -- are not files: they are the user's arguments, answered by root argsAsArray "
                + "and root argsAsHash."})
    List<Path> files;

    /** {@code smc run} on {@code io}'s streams, ended early when a signal from {@code stops} fires. */
    RunCommand(Io io, Supplier<StopSignal> stops) {
        this.io = io;
        this.stops = stops;
    }

    @Override
    public Integer call() throws Exception {
        List<String> given = spec.commandLine().getParseResult().originalArgs();
        int dashes = given.indexOf("--");
        List<Path> toRun = files;
        if (dashes >= 0) {
            int userCount = given.size() - dashes - 1;
            options.userArguments = List.copyOf(given.subList(dashes + 1, given.size()));
            toRun = files.subList(0, files.size() - userCount);
            if (toRun.isEmpty()) {
                throw new picocli.CommandLine.ParameterException(spec.commandLine(), "no files to run before --");
            }
        }
        try (StopSignal stop = stops.get()) {
            int status = options.withBootedCell(spec, io, toRun, stop, cell -> {
                cell.runTimers(stop);
                return cell.exitStatus().orElse(cell.clean() ? 0 : 1);
            });
            if (stop.triggered()) {
                io.stderr().println(spec.qualifiedName() + ": stopped: " + stop.reason());
                io.stderr().flush();
                return CellOptions.STOPPED;
            }
            return status;
        }
    }
}
