package net.smc.demo;

import java.util.concurrent.Callable;
import java.util.function.Supplier;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.IVersionProvider;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * Start here: the {@code smc} command, with the subcommands {@code demo} ({@link DemoCommand}), {@code run} ({@link RunCommand}),
 * {@code shell} ({@link ShellCommand}), {@code validate} ({@link ValidateCommand}),
 * {@code keys} ({@link KeysCommand}), {@code node} ({@link NodeCommand}) and {@code status}
 * ({@link StatusCommand}). Only {@link #main} touches the process (its streams, its exit status, and
 * the shutdown hook that stops a node); {@link #commandLine(Io)} builds the same command on any streams.
 */
@Command(name = "smc", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        synopsisSubcommandLabel = "COMMAND",
        description = "Runs PonderTalk policy scripts in a self-managed cell's policy engine, checks missions, "
                + "runs a vehicle's cell on the network, and asks running nodes for their status.",
        footer = {"%nRun 'smc COMMAND --help' for a command's options and exit statuses.",
            "Exit status 2 means a usage error; the commands explain their other statuses."})
public final class Main implements Callable<Integer> {
    /** The version {@code --version} shows; keep it in step with the build's {@code version}. */
    static final String VERSION = "0.1.0-SNAPSHOT";

    @Spec
    CommandSpec spec;

    public static void main(String[] args) {
        System.exit(commandLine(Io.system()).execute(args));
    }

    /**
     * The {@code smc} command reading and writing {@code io}'s streams; {@code smc node} and
     * {@code smc run} stop when the JVM shuts down (SIGTERM, SIGINT).
     */
    static CommandLine commandLine(Io io) {
        return commandLine(io, StopSignal::onShutdown);
    }

    /** The {@code smc} command, whose {@code node} runs (and {@code run} may run) until a signal from {@code stops} fires. */
    static CommandLine commandLine(Io io, Supplier<StopSignal> stops) {
        CommandLine commandLine = new CommandLine(new Main())
                .addSubcommand(new DemoCommand(io))
                .addSubcommand(new CommandLine(new ExperimentCommand()).addSubcommand(new SetupTimeCommand(io)))
                .addSubcommand(new KeysCommand(io))
                .addSubcommand(new NodeCommand(io, stops))
                .addSubcommand(new RunCommand(io, stops))
                .addSubcommand(new ShellCommand(io))
                .addSubcommand(new StatusCommand(io))
                .addSubcommand(new ValidateCommand(io));
        // After the subcommands are added, so that these settings reach them too.
        commandLine.setOut(io.stdout());
        commandLine.setErr(io.stderr());
        commandLine.setParameterExceptionHandler(new UsageErrors());
        return commandLine;
    }

    /** {@code smc} without a command. */
    @Override
    public Integer call() {
        throw new ParameterException(spec.commandLine(), "no command given: use run, shell, validate, keys, node, status, demo or experiment");
    }

    /** The version line of {@code smc --version} and the subcommands' {@code --version}. */
    static final class Version implements IVersionProvider {
        @Override
        public String[] getVersion() {
            return new String[] {"smc " + VERSION};
        }
    }
}
