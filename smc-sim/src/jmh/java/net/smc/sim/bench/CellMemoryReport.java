package net.smc.sim.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.lang.ref.Reference;
import java.util.Locale;

/**
 * The heap one vehicle's cell takes in a formed team: the used heap after {@code System.gc()}
 * ({@link MemoryMXBean}) once a {@link ScaledTeam} of N vehicles has formed and run 5 more
 * simulated seconds, minus the used heap before it was built, divided by N. It counts everything
 * the team holds per vehicle: the cell with its loaded role policies and protocol state, its
 * endpoint on the simulated network, the messages in flight and the harness's bookkeeping (the
 * generated mission itself is loaded before the first measurement and not counted). Not a JMH
 * benchmark: a plain main, taking the team sizes (default 100 1000) and the number of rounds of each
 * (default 2; a first, uncounted round with 100 vehicles warms up class loading), e.g.
 * <pre>./gradlew :smc-sim:jmh -PjmhMain=net.smc.sim.bench.CellMemoryReport -PjmhArgs='100 1000 10000'</pre>
 */
public final class CellMemoryReport {
    private static final MemoryMXBean MEMORY = ManagementFactory.getMemoryMXBean();

    private CellMemoryReport() {
    }

    public static void main(String[] args) {
        int[] sizes = args.length == 0 ? new int[] {100, 1000} : java.util.Arrays.stream(args).mapToInt(Integer::parseInt).toArray();
        System.out.printf(Locale.ROOT, "JVM %s, GC %s, heap max %d MiB, %d processors%n", System.getProperty("java.vm.version"),
                ManagementFactory.getGarbageCollectorMXBeans().get(0).getName(), MEMORY.getHeapMemoryUsage().getMax() >> 20,
                Runtime.getRuntime().availableProcessors());
        measure(100, true);
        for (int n : sizes) {
            new ScaledTeam(n, 1, false);   // loads the generated mission, which is not counted
            for (int round = 0; round < 2; round++) {
                measure(n, false);
            }
        }
    }

    private static void measure(int n, boolean warmUp) {
        long before = usedAfterGc();
        ScaledTeam team = new ScaledTeam(n, 7, false);
        boolean formed = team.form();
        team.sim.run(5_000);
        long after = usedAfterGc();
        System.out.printf(Locale.ROOT, "%,6d vehicles%s: formed %s; heap %,d KiB, %,.1f KiB per vehicle%n", n,
                warmUp ? " (warm-up)" : "", formed, (after - before) >> 10, (after - before) / 1024.0 / n);
        Reference.reachabilityFence(team);
    }

    private static long usedAfterGc() {
        for (int i = 0; i < 3; i++) {
            System.gc();
        }
        return MEMORY.getHeapMemoryUsage().getUsed();
    }
}
