package net.smc.sim.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import net.smc.sim.experiment.MissionGenerator;

/**
 * The idle team of {@link SimulationSpeedBenchmark}, timed by the CPU the simulation's thread uses
 * as well as by the wall clock: on a machine shared with other work, wall time says as much about
 * the neighbours as about the simulation, while the thread's CPU time (read from
 * {@link ThreadMXBean}) moves much less. For each size given (default 10 100 1000) and with the
 * invariant checks on and off: a {@link ScaledTeam} is formed, settles for 5 simulated seconds, runs
 * {@code --warm S} simulated seconds untimed (default 5), then {@code --steady S} timed (default 10);
 * {@code --com-timeout MS} gives the missions that heartbeat period instead of
 * {@link MissionGenerator#COM_TIMEOUT_MILLIS} (the failure timeout six of it).
 * Printed: simulated seconds per wall second and per CPU second of the simulation's thread, and the
 * steady-state traffic of the timed seconds: bytes and datagrams sent per vehicle per second (as
 * {@link ScaledTeam} counts them, the bytes both as handed to the simulated network and in the real
 * security envelopes, {@link ScaledTeam#wireBytes}; simulated, so the same on any machine). Not a JMH benchmark; for
 * comparing two builds back to back.
 * <pre>./gradlew :smc-sim:jmh -PjmhMain=net.smc.sim.bench.IdleCpuReport -PjmhArgs='10 100 1000 --steady 10'</pre>
 */
public final class IdleCpuReport {
    private IdleCpuReport() {
    }

    public static void main(String[] args) {
        List<Integer> sizes = new ArrayList<>();
        int steady = 10;
        int warm = 5;
        long comTimeout = MissionGenerator.COM_TIMEOUT_MILLIS;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--steady" -> steady = Integer.parseInt(args[++i]);
                case "--warm" -> warm = Integer.parseInt(args[++i]);
                case "--com-timeout" -> comTimeout = Long.parseLong(args[++i]);
                default -> sizes.add(Integer.parseInt(args[i]));
            }
        }
        if (sizes.isEmpty()) {
            sizes.addAll(List.of(10, 100, 1000));
        }
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        if (!threads.isCurrentThreadCpuTimeSupported()) {
            throw new IllegalStateException("this JVM cannot measure a thread's CPU time");
        }
        threads.setThreadCpuTimeEnabled(true);
        System.out.println("vehicles,invariants,simulated_s,wall_s,cpu_s,simulated_per_wall_s,simulated_per_cpu_s,"
                + "bytes_per_vehicle_s,wire_bytes_per_vehicle_s,datagrams_per_vehicle_s");
        for (int n : sizes) {
            for (boolean invariants : new boolean[] {true, false}) {
                ScaledTeam team = new ScaledTeam(n, 1, invariants, comTimeout);
                if (!team.form()) {
                    throw new IllegalStateException(n + " vehicles did not form within "
                            + ScaledTeam.FORMATION_LIMIT_MILLIS + " simulated ms");
                }
                team.sim.run(5_000 + warm * 1_000L);
                long bytes0 = team.bytes();
                long wire0 = team.wireBytes();
                long datagrams0 = team.datagrams();
                long cpu0 = threads.getCurrentThreadCpuTime();
                long wall0 = System.nanoTime();
                team.sim.run(steady * 1_000L);
                double cpu = (threads.getCurrentThreadCpuTime() - cpu0) / 1e9;
                double wall = (System.nanoTime() - wall0) / 1e9;
                double vehicleSeconds = (double) n * steady;
                System.out.printf(Locale.ROOT, "%d,%s,%d,%.3f,%.3f,%.2f,%.2f,%.1f,%.1f,%.2f%n", n, invariants, steady, wall,
                        cpu, steady / wall, steady / cpu, (team.bytes() - bytes0) / vehicleSeconds,
                        (team.wireBytes() - wire0) / vehicleSeconds,
                        (team.datagrams() - datagrams0) / vehicleSeconds);
            }
        }
    }
}
