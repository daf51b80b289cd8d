package net.smc.demo;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import net.smc.core.mission.Colocation;
import net.smc.core.mission.ManagementTree;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionError;
import net.smc.core.mission.MissionException;
import net.smc.core.mission.MissionLoader;
import net.smc.core.mission.MissionRole;
import net.smc.core.mission.Parameter;
import net.smc.policy.api.PolicyRepository;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code smc validate INSTANCE.xml}: loads a mission instance and its class as the acting
 * commander would ({@link MissionLoader}), and prints the resolved mission or every error.
 */
@Command(name = "validate", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {
            "Checks a mission instance file and the mission class file it names (<missionClass href=...>), "
                    + "and resolves every policy URI in the policy repository; each policy must parse and fit one policy reply "
                    + "(65000 bytes of text).",
            "A valid mission is printed to standard output: its parameters, its roles with their "
                    + "cardinalities (minimal..optimal), requirements and policies, the management tree "
                    + "and the colocation rules. Otherwise every error of both files goes to standard "
                    + "error as FILE:LINE:COL: <element>: message; the rule broken follows the ';'.",
            "The formats are described in missions/README.md."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:the mission is valid",
            "1:the instance or its class breaks a rule (every error is listed)",
            "2:usage error: unknown option, a file that cannot be read, no policy repository"})
final class ValidateCommand implements Callable<Integer> {
    private final Io io;

    @Spec
    CommandSpec spec;

    @Option(names = "--repository", paramLabel = "DIR",
            description = "The policy repository the policy URIs resolve against "
                    + "(default: the " + CellOptions.DEFAULT_REPOSITORY + "/ folder of the current directory).")
    Path repository;

    @Option(names = "--allow-path", paramLabel = "DIR",
            description = "Also allow the instance's <missionClass href> to name a file in DIR or below "
                    + "(repeatable; by default only the instance's own folder and below).")
    List<Path> allowPaths = new java.util.ArrayList<>();

    @Parameters(arity = "1", paramLabel = "INSTANCE.xml", description = "The mission instance file.")
    Path instance;

    ValidateCommand(Io io) {
        this.io = io;
    }

    @Override
    public Integer call() {
        Path file = CellOptions.readableFiles(spec, io.workingDir(), List.of(instance)).get(0);
        MissionLoader loader = new MissionLoader(repository(), CellOptions.allowedFolders(spec, io.workingDir(), allowPaths));
        Mission mission;
        try {
            mission = loader.load(file);
        } catch (IOException e) {
            throw new ParameterException(spec.commandLine(), "cannot read '" + instance + "': " + e.getMessage());
        } catch (MissionException e) {
            for (MissionError error : e.errors()) {
                io.stderr().println(error);
            }
            io.stderr().flush();
            return 1;
        }
        print(mission, io.stdout());
        io.stdout().flush();
        return 0;
    }

    private PolicyRepository repository() {
        Path dir = io.workingDir().resolve(repository == null ? Path.of(CellOptions.DEFAULT_REPOSITORY) : repository);
        if (!Files.isDirectory(dir)) {
            String option = repository == null ? "no --repository given and no " + CellOptions.DEFAULT_REPOSITORY
                    + "/ folder in the current directory" : "--repository '" + repository + "': "
                    + (Files.exists(dir) ? "not a directory" : "no such directory");
            throw new ParameterException(spec.commandLine(), option + "; policy URIs need a repository to resolve in");
        }
        return new PolicyRepository(dir);
    }

    /** The resolved mission, one section per aspect, in the class file's order. */
    static void print(Mission mission, PrintWriter out) {
        out.println("mission " + mission.instanceName() + " (class " + mission.className() + ")");
        out.println("parameters:");
        if (mission.parameters().isEmpty()) {
            out.println("  (none)");
        }
        for (Parameter parameter : mission.parameters().values()) {
            out.println("  " + parameter.name() + " = " + parameter.text() + " (" + parameter.type().xmlName() + ")");
        }
        int width = mission.roles().stream().mapToInt(r -> r.name().length()).max().orElse(0);
        out.println("roles (minimal..optimal):");
        for (MissionRole role : mission.roles()) {
            out.println("  " + pad(role.name(), width) + "  " + role.cardinality()
                    + role.primary().map(p -> "  secondary to " + p).orElse("")
                    + "  needs " + role.requirement().describe());
            role.policies().forEach(uri -> out.println("    policy " + uri));
            role.authorisations().forEach(uri -> out.println("    authorisation " + uri));
        }
        out.println("management tree:");
        ManagementTree tree = mission.tree();
        Map<String, Integer> depths = tree.depths();
        for (String role : tree.depthFirst()) {
            int depth = depths.get(role);
            // indented by its level, up to MAX_INDENT levels (a chain of thousands of managers is valid)
            out.println("  " + "  ".repeat(Math.min(depth, MAX_INDENT)) + role + (depth > MAX_INDENT ? "  (level " + depth + ")" : ""));
        }
        out.println("colocation:");
        Colocation colocation = mission.colocation();
        if (colocation.parallel().isEmpty() && colocation.exclusive().isEmpty()) {
            out.println("  (none: one role per vehicle)");
        }
        for (Colocation.Parallel rule : colocation.parallel()) {
            out.println("  " + rule.role() + " runs in parallel with " + String.join(" or ", rule.with()));
        }
        for (Colocation.Exclusive rule : colocation.exclusive()) {
            out.println("  " + String.join(" and ", rule.roles()) + " share a vehicle, one active at a time");
        }
    }

    /** The deepest level the listing of the management tree indents; deeper roles name their level. */
    static final int MAX_INDENT = 20;

    private static String pad(String text, int width) {
        return text + " ".repeat(width - text.length());
    }
}
