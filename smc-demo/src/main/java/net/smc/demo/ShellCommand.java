package net.smc.demo;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import net.smc.policy.PolicyEngine;
import net.smc.policy.RunResult;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code smc shell [FILE.p2 ...]}: boots the files, then runs statements read from stdin. */
@Command(name = "shell", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {
            "Runs the files as boot units of one fresh cell (as run does), ends the boot phase, then "
                    + "reads PonderTalk from standard input and runs each input as one unit.",
            "An input ends at a line whose last non-blank character is '.' (even when that '.' is "
                    + "inside a string or a comment); text left at the end of input without one is run too. "
                    + "Variables persist from one input to the next. After an input that ran without error "
                    + "the printed form of its last statement's value goes to standard output; "
                    + "errors go to standard error and the shell goes on.",
            "In errors an input is named stdin, its lines counted from 1 within that input.",
            "On a terminal the shell prompts with 'smc> ' (and '...> ' for an input's further lines), "
                    + "edits the line (arrows, Ctrl-A/E, Ctrl-R) and keeps a history in ~/.smc_history; "
                    + "Ctrl-D ends the input, Ctrl-C drops the line being edited."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:the end of input was reached (errors in the files or the inputs do not change this)",
            "2:usage error: unknown option, bad --auth value, a file that cannot be read",
            "n:a file or an input ran root exit: n (root exit is 0); nothing more runs"})
final class ShellCommand implements Callable<Integer> {
    /** The source name of shell inputs in diagnostics. */
    static final String SOURCE = "stdin";

    private final Io io;

    @Spec
    CommandSpec spec;

    @Mixin
    CellOptions options;

    @Parameters(arity = "0..*", paramLabel = "FILE.p2", description = "Files to run first, in order, as boot units.")
    List<Path> files = new ArrayList<>();

    ShellCommand(Io io) {
        this.io = io;
    }

    @Override
    public Integer call() throws Exception {
        return options.withBootedCell(spec, io, files, cell -> {
            if (cell.exitStatus().isEmpty()) {
                readInputs(cell);
            }
            return cell.exitStatus().orElse(0);
        });
    }

    private void readInputs(CommandCell cell) throws IOException {
        if (io.interactive() && io.stdin() == System.in) {
            try (TerminalLines terminal = TerminalLines.open(Path.of(System.getProperty("user.home"), ".smc_history"))) {
                readInputs(cell, new ShellInput(terminal));
            }
            return;
        }
        readInputs(cell, new ShellInput(io));
    }

    private void readInputs(CommandCell cell, ShellInput input) throws IOException {
        PolicyEngine.Session session = cell.cell().session();
        for (String text = input.next(io.stderr()::println); text != null; text = input.next(io.stderr()::println)) {
            cell.cell().timers().runDue();   // the shell runs due timers between inputs, never while it waits
            if (cell.exitStatus().isPresent()) {
                return;
            }
            RunResult result = session.run(SOURCE, text);
            if (result.ok()) {
                io.stdout().println(PolicyEngine.print(result.value()));
            }
            if (cell.exitStatus().isPresent()) {
                return;
            }
        }
    }
}
