package net.smc.demo;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

import javax.imageio.ImageIO;

import net.smc.sim.render.GifRecorder;
import net.smc.sim.render.NoDisplayException;
import net.smc.sim.render.PacedLoop;
import net.smc.sim.render.ViewControls;
import net.smc.sim.render.WorldPainter;
import net.smc.sim.render.WorldWindow;
import net.smc.sim.scenario.RescueScenario;
import net.smc.sim.team.TeamSimulation;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code smc demo [rescue|reconnaissance] [--seed N] [--out DIR] [--gui] [--speed X] [--loss P] [--limit S]
 * [--transport sim|udp]}: runs the paper's rescue (section IV-C) with cells and policies in the
 * simulated world, prints its timeline as it happens, and writes {@code rescue.png} (in the spirit
 * of Fig. 7), {@code rescue.gif} and {@code rescue-timeline.csv} into DIR. Exit 0 when assistance
 * reached the soldier, 1 (with the reason) when not, 2 for a usage error. {@code --transport udp}
 * runs it on real UDP ({@link UdpRescueDemo}). {@code reconnaissance} runs the reconnaissance of
 * section II-A instead ({@link ReconnaissanceDemo}).
 */
@Command(name = "demo", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = "Run a scenario of the paper in the simulated world: its timeline, a picture, a film, a CSV.")
final class DemoCommand implements Callable<Integer> {
    private final Io io;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", defaultValue = "rescue", paramLabel = "SCENARIO",
            description = "rescue (default) or reconnaissance")
    String scenario;

    @Option(names = "--seed", defaultValue = "1", description = "seed of every random draw (default 1)")
    long seed;

    @Option(names = "--out", defaultValue = "build/demo", paramLabel = "DIR", description = "where the files go (default build/demo)")
    Path out;

    @Option(names = "--gui", description = "show the world in a window while it runs (headless without a display)")
    boolean gui;

    @Option(names = "--speed", defaultValue = "1", paramLabel = "X",
            description = "with --gui, or with --transport udp: mission seconds per wall second (default 1)")
    double speed;

    @Option(names = "--loss", defaultValue = "0", paramLabel = "P", description = "extra datagram loss, 0 to below 1 (default 0)")
    double loss;

    @Option(names = "--limit", paramLabel = "SECONDS",
            description = "mission time after which the run gives up (default 180 for the rescue, 900 for the reconnaissance)")
    Double limit;

    @Option(names = "--transport", defaultValue = "sim", paramLabel = "sim|udp",
            description = "sim: the world's simulated radio, on a virtual clock (default); udp: every cell on its own UDP "
                    + "sockets on loopback, the world stepped in real time")
    String transport;

    /** The slowest --speed: a hundredth of real time (slower, a udp run or a window would seem to hang). */
    static final double MIN_SPEED = 0.01;
    /** The shortest --limit, seconds: the mission clock counts whole milliseconds. */
    static final double MIN_LIMIT = 0.001;

    DemoCommand(Io io) {
        this.io = io;
    }

    @Override
    public Integer call() throws Exception {
        if (!scenario.equals("rescue") && !scenario.equals("reconnaissance")) {
            throw new ParameterException(spec.commandLine(), "unknown scenario '" + scenario + "'; scenarios: rescue, reconnaissance");
        }
        if (!transport.equals("sim") && !transport.equals("udp")) {
            throw new ParameterException(spec.commandLine(), "--transport '" + transport + "' is unknown; use sim or udp");
        }
        if (transport.equals("udp") && scenario.equals("reconnaissance")) {
            throw new ParameterException(spec.commandLine(), "--transport udp is available for the rescue only; run the reconnaissance with sim");
        }
        if (transport.equals("udp") && gui) {
            throw new ParameterException(spec.commandLine(), "--gui is for --transport sim only; with udp the run writes its files");
        }
        if (transport.equals("udp") && speed > 100) {
            throw new ParameterException(spec.commandLine(), "--speed " + speed + " with --transport udp must be at most 100"
                    + " (the cells' timers and the world run on the wall clock times the speed)");
        }
        if (!(loss >= 0 && loss < 1)) {
            throw new ParameterException(spec.commandLine(), "--loss " + loss + " is out of range; it must be 0 or more and below 1");
        }
        if (!(speed >= MIN_SPEED) || Double.isInfinite(speed)) {
            throw new ParameterException(spec.commandLine(), "--speed " + speed + " must be a number of at least " + MIN_SPEED
                    + " (mission seconds per wall second)");
        }
        if (limit != null && (!(limit >= MIN_LIMIT) || limit > 86_400)) {
            throw new ParameterException(spec.commandLine(), "--limit " + limit + " must be at least " + MIN_LIMIT
                    + " (1 ms) and at most 86400 seconds");
        }
        Path dir = OutFolder.make(spec, io.workingDir(), out);
        if (scenario.equals("reconnaissance")) {
            try {
                return new ReconnaissanceDemo(io).run(seed, loss, limit == null ? -1 : Math.round(limit * 1000), gui, speed, dir);
            } catch (IOException e) {
                io.stderr().println("smc demo: " + OutFolder.reason(e));
                return 1;
            }
        }
        long limitMillis = Math.round((limit == null ? 180 : limit) * 1000);
        if (transport.equals("udp")) {
            try {
                return new UdpRescueDemo(io).run(seed, dir, loss, limitMillis, speed);
            } catch (IOException e) {
                io.stderr().println("smc demo: " + OutFolder.reason(e));
                return 1;
            }
        }
        RescueScenario.Settings settings = RescueScenario.Settings.of(seed).withLoss(loss).withLimit(limitMillis)
                .withSecurity(TeamSimulation.Security.REAL).withFilm(GifRecorder.Settings.defaults());
        io.stdout().println("rescue of a wounded soldier (section IV-C), seed " + seed + ", loss " + loss
                + ", signed traffic over the world's radio");
        RescueScenario rescue;
        try {
            rescue = RescueScenario.load(io.workingDir(), settings, row -> io.stdout().println(RescueScenario.format(row)));
        } catch (IOException e) {
            io.stderr().println("smc demo: " + e.getMessage());
            return 1;
        }
        long wall = System.nanoTime();
        rescue.start();
        if (gui) {
            runWithWindow(rescue);
        }
        rescue.advance(Long.MAX_VALUE);
        RescueScenario.Outcome outcome = rescue.finish();
        double wallSeconds = (System.nanoTime() - wall) / 1e9;
        BufferedImage png = new WorldPainter().render(rescue.world(), rescue.scene(), 1200, 860);
        try {
            writePng(png, dir.resolve("rescue.png"));
            rescue.film().orElseThrow().write(dir.resolve("rescue.gif"));
            rescue.timeline().writeCsv(dir.resolve("rescue-timeline.csv"));
        } catch (IOException e) {
            io.stderr().println("smc demo: cannot write the run's files in " + dir + ": " + OutFolder.reason(e));
            return 1;
        }
        io.stdout().println(String.format(Locale.ROOT, "%.1f s of mission time in %.1f s (%.1fx real time); files in %s",
                outcome.missionMillis() / 1000.0, wallSeconds, outcome.missionMillis() / 1000.0 / wallSeconds, dir));
        rescue.diagnostics().forEach((vehicle, errors) -> errors.forEach(e -> io.stderr().println(vehicle + ": " + e)));
        if (outcome.succeeded()) {
            io.stdout().println("succeeded: " + outcome.reason());
            return 0;
        }
        io.stdout().println("failed: " + outcome.reason());
        return 1;
    }

    /** Writes {@code image} as a PNG file, failing with the file named when it cannot be (a folder of that name, say). */
    static void writePng(BufferedImage image, Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new java.nio.file.FileSystemException(file.toString(), null, "a folder of that name is there");
        }
        ImageIO.write(image, "png", file.toFile());
    }

    private void runWithWindow(RescueScenario rescue) throws InterruptedException {
        ViewControls controls = new ViewControls(speed, net.smc.sim.render.Overlays.defaults());
        try (WorldWindow window = WorldWindow.open("smc demo rescue", 1200, 860, controls)) {
            PacedLoop.realTime(window.controls(), 40).run(rescue::advance, () -> window.show(rescue.world(), rescue.scene()),
                    () -> window.closed() || rescue.finished());
        } catch (NoDisplayException e) {
            io.stdout().println(e.getMessage());
        }
    }
}
