package net.smc.demo;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.function.IntFunction;

import net.smc.core.cell.Scheme;
import net.smc.sim.experiment.SetupResult;

/**
 * The shape of a set-up time experiment, read off its medians (nearest rank, complete runs only),
 * per transport: each scheme's median at every number of roles, how much it grows from its fewest
 * roles, the centralised median over the distributed one, and where the faster scheme changes.
 * These are the figures the paper's Fig. 8 is read for (how flat the distributed scheme stays, how
 * far ahead of the centralised one it ends, where the two cross), so a run states them itself
 * instead of leaving them to be worked out from the CSV.
 *
 * <pre>
 * shape of the medians (sim):
 *   roles                           5      10      20      50
 *   distributed, ms                72      81      92     116
 *   centralised, ms                31      39      57     201
 *   distributed x its 5 roles    1.00    1.13    1.28    1.61
 *   centralised x its 5 roles    1.00    1.26    1.84    6.48
 *   centralised / distributed    0.43    0.48    0.62    1.73
 *   centralised faster up to 20 roles, distributed from 50: the medians cross between 20 and 50 roles
 * </pre>
 * A point with no complete run shows "-".
 */
final class SetupTimeShape {
    private static final String LABEL = "  %-28s";
    private static final String CELL = "%8s";

    private SetupTimeShape() {
    }

    /** The shape of {@code results}: one block per transport, in the order sim, udp; empty if there are none. */
    static String describe(List<SetupResult> results) {
        // transport -> scheme -> roles -> complete set-up times
        Map<String, Map<Scheme, Map<Integer, List<Double>>>> runs = new TreeMap<>();
        for (SetupResult r : results) {
            List<Double> times = runs.computeIfAbsent(r.transport(), t -> new TreeMap<>())
                    .computeIfAbsent(r.scheme(), s -> new TreeMap<>()).computeIfAbsent(r.roles(), n -> new ArrayList<>());
            if (r.complete()) {
                times.add(r.setupMillis());
            }
        }
        StringBuilder out = new StringBuilder();
        for (Map.Entry<String, Map<Scheme, Map<Integer, List<Double>>>> t : runs.entrySet()) {
            TreeSet<Integer> roles = new TreeSet<>();
            t.getValue().values().forEach(points -> roles.addAll(points.keySet()));
            out.append(block(t.getKey(), List.copyOf(roles), medians(t.getValue())));
        }
        return out.toString();
    }

    /** Per scheme, per number of roles: the median of the complete runs, or null when there is none. */
    private static Map<Scheme, Map<Integer, Double>> medians(Map<Scheme, Map<Integer, List<Double>>> runs) {
        Map<Scheme, Map<Integer, Double>> medians = new TreeMap<>();
        runs.forEach((scheme, points) -> {
            Map<Integer, Double> m = new TreeMap<>();
            points.forEach((n, times) -> m.put(n, times.isEmpty() ? null
                    : SetupTimeChart.rank(SetupTimeChart.sortedCopy(times), 0.5)));
            medians.put(scheme, m);
        });
        return medians;
    }

    private static String block(String transport, List<Integer> roles, Map<Scheme, Map<Integer, Double>> medians) {
        StringBuilder b = new StringBuilder("shape of the medians (" + transport + "):\n");
        row(b, "roles", roles, n -> String.valueOf(n));
        for (Map.Entry<Scheme, Map<Integer, Double>> s : medians.entrySet()) {
            row(b, name(s.getKey()) + ", ms", roles, n -> format(s.getValue().get(n), "%.0f"));
        }
        for (Map.Entry<Scheme, Map<Integer, Double>> s : medians.entrySet()) {
            Integer fewest = s.getValue().entrySet().stream().filter(e -> e.getValue() != null).map(Map.Entry::getKey)
                    .findFirst().orElse(null);
            if (fewest != null) {
                double base = s.getValue().get(fewest);
                row(b, name(s.getKey()) + " x its " + fewest + " roles", roles,
                        n -> format(ratio(s.getValue().get(n), base), "%.2f"));
            }
        }
        Map<Integer, Double> distributed = medians.get(Scheme.DISTRIBUTED);
        Map<Integer, Double> centralised = medians.get(Scheme.CENTRALISED);
        if (distributed != null && centralised != null) {
            row(b, "centralised / distributed", roles,
                    n -> format(ratio(centralised.get(n), distributed.get(n)), "%.2f"));
            String faster = faster(roles, distributed, centralised);
            if (!faster.isEmpty()) {
                b.append("  ").append(faster).append('\n');
            }
        }
        return b.toString();
    }

    /**
     * Which scheme's median is lower, over the numbers of roles both have: one scheme throughout, a
     * single change (where they cross), or, when they change more than once or tie, each point named.
     */
    static String faster(List<Integer> roles, Map<Integer, Double> distributed, Map<Integer, Double> centralised) {
        List<Integer> points = new ArrayList<>();
        List<String> winners = new ArrayList<>();
        for (int n : roles) {
            Double d = distributed.get(n);
            Double c = centralised.get(n);
            if (d != null && c != null) {
                points.add(n);
                winners.add(d < c ? "distributed" : c < d ? "centralised" : "neither");
            }
        }
        if (points.isEmpty()) {
            return "";
        }
        int changes = 0;
        int last = 0;
        for (int i = 1; i < points.size(); i++) {
            if (!winners.get(i).equals(winners.get(i - 1))) {
                changes++;
                last = i;
            }
        }
        if (winners.contains("neither") || changes > 1) {
            StringBuilder s = new StringBuilder("faster by the medians:");
            for (int i = 0; i < points.size(); i++) {
                s.append(i == 0 ? " " : ", ").append(winners.get(i)).append(" at ").append(points.get(i));
            }
            boolean tie = winners.contains("neither");
            return s.append(tie ? " roles" : " roles (the medians cross " + changes + " times)").toString();
        }
        if (changes == 0) {
            return winners.get(0) + " faster at every number of roles (" + points.get(0) + " to "
                    + points.get(points.size() - 1) + ")";
        }
        int before = points.get(last - 1);
        int after = points.get(last);
        return winners.get(0) + " faster up to " + before + " roles, " + winners.get(last) + " from " + after
                + ": the medians cross between " + before + " and " + after + " roles";
    }

    private static Double ratio(Double a, Double b) {
        return a == null || b == null || b == 0 ? null : a / b;
    }

    private static String format(Double v, String pattern) {
        return v == null ? "-" : String.format(Locale.ROOT, pattern, v);
    }

    private static String name(Scheme s) {
        return s.name().toLowerCase(Locale.ROOT);
    }

    private static void row(StringBuilder b, String label, List<Integer> roles, IntFunction<String> cell) {
        b.append(String.format(Locale.ROOT, LABEL, label));
        for (int n : roles) {
            b.append(String.format(Locale.ROOT, CELL, cell.apply(n)));
        }
        b.append('\n');
    }
}
