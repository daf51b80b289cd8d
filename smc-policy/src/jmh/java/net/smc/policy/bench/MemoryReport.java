package net.smc.policy.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.lang.ref.Reference;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import javax.management.ObjectName;
import net.smc.policy.api.AuthMode;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.runtime.Domain;

/**
 * Goal: know the heap an idle cell retains, and the heap each loaded obligation policy adds.
 * Measured as the difference in used heap ({@link MemoryMXBean}, after {@code System.gc()})
 * around making 1,000 idle cells (kept alive), and around loading 1,000 policies (the text of
 * {@link LoadBench}) into a cell that already holds their templates; divided by 1,000. The same
 * differences are also taken from live class histograms (the JVM's {@code GC.class_histogram},
 * exact live bytes), which also show which classes the bytes are. Not a JMH benchmark: a plain
 * main, e.g.
 * <pre>
 * ./gradlew :smc-policy:jmhClasses
 * java -cp smc-policy/build/classes/java/jmh:smc-policy/build/classes/java/main net.smc.policy.bench.MemoryReport
 * </pre>
 */
public final class MemoryReport {
    private static final int N = 1000;
    private static final MemoryMXBean MEMORY = ManagementFactory.getMemoryMXBean();

    private MemoryReport() {
    }

    public static void main(String[] args) throws Exception {
        int rounds = args.length > 0 ? Integer.parseInt(args[0]) : 3;
        System.out.printf("JVM %s, GC %s, heap max %d MiB; bytes per item over %,d items%n",
                System.getProperty("java.vm.version"), ManagementFactory.getGarbageCollectorMXBeans().get(0).getName(),
                MEMORY.getHeapMemoryUsage().getMax() >> 20, N);
        for (int round = 0; round <= rounds; round++) {   // round 0 warms up: class loading, dispatch tables
            boolean show = round == rounds;
            String line = String.format("round %d: idle cell %s; event template %s; obligation policy %s",
                    round, measure(() -> MemoryReport::idleCells, false), measure(MemoryReport::templates, false),
                    measure(MemoryReport::policies, show));
            System.out.println(round == 0 ? line + " (warm-up)" : line);
        }
    }

    /** 1,000 idle cells ({@code PolicyEngine.builder().build()}). */
    private static Object idleCells() {
        PolicyEngine[] cells = new PolicyEngine[N];
        for (int i = 0; i < N; i++) {
            cells[i] = PolicyEngine.builder().build();
        }
        return cells;
    }

    private static final String TEMPLATES = Bench.templates("e", N);
    private static final String POLICIES = "store := #() asHash. root at: \"store\" put: store.\n"
            + Bench.policies("p", "e", N, "k");

    /** Setup (not counted): a cell. Counted: 1,000 event templates run into it. */
    private static Supplier<Object> templates() {
        List<Diagnostic> errors = Bench.errors();
        PolicyEngine cell = Bench.cell(AuthMode.OFF, errors);
        return () -> {
            Bench.run(cell, "templates", TEMPLATES, errors);
            check(cell, "root/event");
            return cell;
        };
    }

    /** Setup (not counted): a cell with 1,000 templates. Counted: 1,000 obligation policies loaded into it. */
    private static Supplier<Object> policies() {
        List<Diagnostic> errors = Bench.errors();
        PolicyEngine cell = Bench.cell(AuthMode.OFF, errors);
        Bench.run(cell, "templates", TEMPLATES, errors);
        return () -> {
            Bench.run(cell, "policies", POLICIES, errors);
            check(cell, "root/policy");
            return cell;
        };
    }

    /**
     * Runs {@link #measureHere} in a thread of its own, so that no stale stack slot of an earlier
     * measurement keeps its objects alive into this one's "before" (seen with the serial collector).
     */
    private static String measure(Supplier<Supplier<Object>> setup, boolean showClasses) throws Exception {
        String[] result = new String[1];
        Exception[] failure = new Exception[1];
        Thread thread = new Thread(() -> {
            try {
                result[0] = measureHere(setup, showClasses);
            } catch (Exception e) {
                failure[0] = e;
            }
        });
        thread.start();
        thread.join();
        if (failure[0] != null) {
            throw failure[0];
        }
        return result[0];
    }

    /** Heap used after GC and live histogram, after {@code setup} and after the work it answers, per item. */
    private static String measureHere(Supplier<Supplier<Object>> setup, boolean showClasses) throws Exception {
        Supplier<Object> work = setup.get();
        long usedBefore = usedAfterGc();
        Map<String, Long> before = histogram();
        Object kept = work.get();
        long usedAfter = usedAfterGc();
        Map<String, Long> after = histogram();
        Reference.reachabilityFence(kept);
        Reference.reachabilityFence(work);
        long live = after.get("Total") - before.get("Total");
        if (showClasses) {
            System.out.println("  largest classes per obligation policy (live histogram difference / " + N + "):");
            after.entrySet().stream().filter(e -> !e.getKey().equals("Total"))
                    .map(e -> Map.entry(e.getKey(), e.getValue() - before.getOrDefault(e.getKey(), 0L)))
                    .sorted((a, b) -> Long.compare(b.getValue(), a.getValue())).limit(14)
                    .forEach(e -> System.out.printf("    %6.1f B  %s%n", e.getValue() / (double) N, e.getKey()));
        }
        return String.format("%,d B (histogram %,d B)", (usedAfter - usedBefore) / N, live / N);
    }

    private static void check(PolicyEngine cell, String domain) {
        Bench.check(((Domain) cell.resolve(domain)).entries().size() == N, domain + " size");
    }

    private static long usedAfterGc() {
        System.gc();
        System.gc();
        return MEMORY.getHeapMemoryUsage().getUsed();
    }

    /** Live bytes by class, and "Total", from the JVM's GC.class_histogram (which collects first). */
    private static Map<String, Long> histogram() throws Exception {
        String text = (String) ManagementFactory.getPlatformMBeanServer().invoke(
                new ObjectName("com.sun.management:type=DiagnosticCommand"), "gcClassHistogram",
                new Object[] {new String[0]}, new String[] {String[].class.getName()});
        Map<String, Long> bytes = new HashMap<>();
        for (String line : text.split("\n")) {
            String[] f = line.trim().split("\\s+");
            if (f.length >= 4 && f[0].endsWith(":")) {
                bytes.merge(f[3], Long.parseLong(f[2]), Long::sum);
            } else if (f.length == 3 && f[0].equals("Total")) {
                bytes.put("Total", Long.parseLong(f[2]));
            }
        }
        return bytes;
    }
}
