package net.smc.sim.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * One team of each size given, formed once and then run idle: the formation's simulated and wall
 * time, the idle simulation speed, and the steady-state traffic per vehicle broken down by message
 * type (the frame's type byte: 0x09 HEARTBEAT, 0x0F STATUS, 0x12 SUBTREE_REPORT ...; see the wire
 * format note), each as the simulated network carries it (its 16-byte seal) and as the real
 * security layer's envelope would ({@link ScaledTeam#wireBytes}). A single run per size, for looking into the figures of {@link FormationBenchmark} and
 * {@link SimulationSpeedBenchmark}; not a JMH benchmark. Arguments: team sizes (default 10 100 1000),
 * {@code --steady S} simulated seconds of idle running (default 10), {@code --no-invariants}.
 * <pre>./gradlew :smc-sim:jmh -PjmhMain=net.smc.sim.bench.TeamScaleReport -PjmhArgs='100 1000 --steady 20'</pre>
 */
public final class TeamScaleReport {
    private TeamScaleReport() {
    }

    public static void main(String[] args) {
        List<Integer> sizes = new ArrayList<>();
        int steady = 10;
        boolean invariants = true;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--steady" -> steady = Integer.parseInt(args[++i]);
                case "--no-invariants" -> invariants = false;
                default -> sizes.add(Integer.parseInt(args[i]));
            }
        }
        if (sizes.isEmpty()) {
            sizes.addAll(List.of(10, 100, 1000));
        }
        System.out.printf(Locale.ROOT, "invariants checked every 50 ms: %s; %d processors%n", invariants,
                Runtime.getRuntime().availableProcessors());
        for (int n : sizes) {
            report(n, steady, invariants);
        }
    }

    private static void report(int n, int steady, boolean invariants) {
        long t0 = System.nanoTime();
        ScaledTeam team = new ScaledTeam(n, 1, invariants);
        long t1 = System.nanoTime();
        boolean formed = team.form(500, seats -> System.out.printf(Locale.ROOT, "  at %,d ms simulated, %.1f s wall: %d of %d seats%n",
                team.sim.nowMillis(), (System.nanoTime() - t1) / 1e9, seats, n - 1));
        long t2 = System.nanoTime();
        System.out.printf(Locale.ROOT, "%,d vehicles: built in %.2f s; formed %s (%d seats) in %d ms simulated, %.1f s wall "
                + "(%.3f simulated s per wall s)%n", n, (t1 - t0) / 1e9, formed, team.acceptedSeats(), team.formationMillis(),
                (t2 - t1) / 1e9, team.sim.nowMillis() / 1e6 / ((t2 - t1) / 1e9) * 1e3);
        long[] datagrams = new long[256];
        long[] bytes = new long[256];
        long[] wire = new long[256];
        for (int c = 0; c < 256; c++) {
            datagrams[c] = team.datagrams(c);
            bytes[c] = team.bytes(c);
            wire[c] = team.wireBytes(c);
        }
        long d = team.datagrams();
        long b = team.bytes();
        long w = team.wireBytes();
        long t3 = System.nanoTime();
        team.sim.run(steady * 1_000L);
        long t4 = System.nanoTime();
        double vehicleSeconds = (double) steady * n;
        System.out.printf(Locale.ROOT, "  idle %d s: %.2f simulated s per wall s; sent %.2f datagrams, %.1f B per vehicle per s"
                        + " (%.1f in the real security envelopes)%n", steady, steady / ((t4 - t3) / 1e9),
                (team.datagrams() - d) / vehicleSeconds, (team.bytes() - b) / vehicleSeconds, (team.wireBytes() - w) / vehicleSeconds);
        for (int c = 0; c < 256; c++) {
            long count = team.datagrams(c) - datagrams[c];
            if (count > 0) {
                System.out.printf(Locale.ROOT, "    type 0x%02X: %.3f datagrams, %.1f B per vehicle per s (%.0f B each; %.0f on the wire)%n",
                        c, count / vehicleSeconds, (team.bytes(c) - bytes[c]) / vehicleSeconds,
                        (team.bytes(c) - bytes[c]) / (double) count, (team.wireBytes(c) - wire[c]) / (double) count);
            }
        }
    }
}
