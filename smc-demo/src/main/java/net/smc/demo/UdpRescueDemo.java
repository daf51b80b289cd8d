package net.smc.demo;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;


import net.smc.core.transport.udp.UdpCounters;
import net.smc.sim.render.GifRecorder;
import net.smc.sim.render.WorldPainter;
import net.smc.sim.scenario.RescueScenario;
import net.smc.sim.team.LiveTeam;

/**
 * {@code smc demo rescue --transport udp}: the rescue with every cell on its own Netty UDP sockets
 * over loopback, signed traffic with keys made for the run, and the simulated world in this
 * process stepped on the wall clock ({@link LiveTeam}), {@code --speed} mission seconds per wall
 * second for the world and the cells alike. The same timeline, files and exit status as on the
 * simulated transport, and a line of what went through the sockets.
 */
final class UdpRescueDemo {
    private final Io io;

    UdpRescueDemo(Io io) {
        this.io = io;
    }

    /** Runs it; 0 when assistance reached the soldier, 1 when not. */
    int run(long seed, Path dir, double loss, long limitMillis, double speed) throws Exception {
        RescueScenario.Settings settings = RescueScenario.Settings.of(seed).withLoss(loss).withLimit(limitMillis)
                .withFilm(GifRecorder.Settings.defaults());
        io.stdout().println("rescue of a wounded soldier (section IV-C), seed " + seed + ", loss " + loss
                + ", every cell on its own UDP sockets on loopback, signed traffic, world in real time x" + speed);
        io.stdout().flush();
        RescueScenario rescue;
        try {
            rescue = RescueScenario.loadLive(io.workingDir(), settings, speed, row -> {
                io.stdout().println(RescueScenario.format(row));
                io.stdout().flush();
            });
        } catch (IOException e) {
            io.stderr().println("smc demo: " + e.getMessage());
            return 1;
        }
        long wall = System.nanoTime();
        RescueScenario.Outcome outcome;
        UdpCounters udp;
        try (rescue) {
            outcome = rescue.run();
            udp = ((LiveTeam) rescue.team()).udpCounters();
            rescue.diagnostics().forEach((vehicle, errors) -> errors.forEach(e -> io.stderr().println(vehicle + ": " + e)));
        }
        double wallSeconds = (System.nanoTime() - wall) / 1e9;
        BufferedImage png = new WorldPainter().render(rescue.world(), rescue.scene(), 1200, 860);
        DemoCommand.writePng(png, dir.resolve("rescue.png"));
        rescue.film().orElseThrow().write(dir.resolve("rescue.gif"));
        rescue.timeline().writeCsv(dir.resolve("rescue-timeline.csv"));
        io.stdout().println(String.format(Locale.ROOT, "%.1f s of mission time in %.1f s of wall time (x%.2f); files in %s",
                outcome.missionMillis() / 1000.0, wallSeconds, outcome.missionMillis() / 1000.0 / wallSeconds, dir));
        io.stdout().println(String.format(Locale.ROOT, "UDP: %d datagrams sent (%d unicast, %d broadcast), %d delivered to cells,"
                + " %d send failures", udp.sent() + udp.broadcastsSent(), udp.sent(), udp.broadcastsSent(), udp.delivered(),
                udp.sendFailures()));
        if (outcome.succeeded()) {
            io.stdout().println("succeeded: " + outcome.reason());
            return 0;
        }
        io.stdout().println("failed: " + outcome.reason());
        return 1;
    }
}
