package net.smc.demo;

import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** {@code smc experiment}: the experiments of the paper's section V; {@code setup-time} is Fig. 8. */
@Command(name = "experiment", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        synopsisSubcommandLabel = "EXPERIMENT",
        description = "Runs an experiment of the paper's section V: setup-time (Fig. 8).")
final class ExperimentCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        throw new ParameterException(spec.commandLine(), "no experiment given: use setup-time");
    }
}
