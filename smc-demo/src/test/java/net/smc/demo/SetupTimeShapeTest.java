package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import net.smc.core.cell.Scheme;
import net.smc.sim.experiment.SetupResult;

class SetupTimeShapeTest {
    private static SetupResult run(int roles, Scheme scheme, String transport, int run, double millis) {
        return new SetupResult(roles, scheme, transport, run, millis, 10, 1_000, 1.0, millis < 0 ? 0 : roles - 1, 0);
    }

    /** Three runs a point, the median the middle one: {@code medians[i]} at {@code roles[i]}. */
    private static List<SetupResult> point(List<SetupResult> into, Scheme scheme, String transport, int[] roles,
                                           double... medians) {
        for (int i = 0; i < roles.length; i++) {
            into.add(run(roles[i], scheme, transport, 1, medians[i] + 5));
            into.add(run(roles[i], scheme, transport, 2, medians[i]));
            into.add(run(roles[i], scheme, transport, 3, medians[i] - 5));
        }
        return into;
    }

    private static Map<Integer, Double> medians(int[] roles, double... values) {
        Map<Integer, Double> m = new HashMap<>();
        for (int i = 0; i < roles.length; i++) {
            m.put(roles[i], values[i]);
        }
        return m;
    }

    @Test
    void tableOfMedians_growthFromTheFewestRoles_ratio_andTheCrossing() {
        int[] roles = {5, 10, 20, 50};
        List<SetupResult> results = new ArrayList<>();
        point(results, Scheme.DISTRIBUTED, "sim", roles, 72, 81, 92, 116);
        point(results, Scheme.CENTRALISED, "sim", roles, 31, 39, 57, 201);
        String shape = SetupTimeShape.describe(results);
        List<String> lines = shape.lines().toList();
        assertEquals("shape of the medians (sim):", lines.get(0), shape);
        assertEquals(List.of("roles", "5", "10", "20", "50"), words(lines.get(1)));
        assertEquals(List.of("distributed,", "ms", "72", "81", "92", "116"), words(lines.get(2)));
        assertEquals(List.of("centralised,", "ms", "31", "39", "57", "201"), words(lines.get(3)));
        assertEquals(List.of("distributed", "x", "its", "5", "roles", "1.00", "1.13", "1.28", "1.61"), words(lines.get(4)));
        assertEquals(List.of("centralised", "x", "its", "5", "roles", "1.00", "1.26", "1.84", "6.48"), words(lines.get(5)));
        assertEquals(List.of("centralised", "/", "distributed", "0.43", "0.48", "0.62", "1.73"), words(lines.get(6)));
        assertEquals("centralised faster up to 20 roles, distributed from 50: the medians cross between 20 and 50 roles",
                lines.get(7).strip());
        assertEquals(8, lines.size(), shape);
    }

    @Test
    void aPointWithNoCompleteRun_showsADash_andTheGrowthStartsAtTheFewestRolesThatHaveOne() {
        List<SetupResult> results = new ArrayList<>();
        results.add(run(5, Scheme.DISTRIBUTED, "sim", 1, -1));
        results.add(run(10, Scheme.DISTRIBUTED, "sim", 1, 80));
        results.add(run(20, Scheme.DISTRIBUTED, "sim", 1, 100));
        List<String> lines = SetupTimeShape.describe(results).lines().toList();
        assertEquals(List.of("distributed,", "ms", "-", "80", "100"), words(lines.get(2)));
        assertEquals(List.of("distributed", "x", "its", "10", "roles", "-", "1.00", "1.25"), words(lines.get(3)));
        assertEquals(4, lines.size(), "one scheme: no ratio between schemes, no crossing: " + lines);
    }

    @Test
    void eachTransportHasItsOwnBlock() {
        List<SetupResult> results = new ArrayList<>();
        point(results, Scheme.DISTRIBUTED, "udp", new int[] {5, 20}, 300, 400);
        point(results, Scheme.CENTRALISED, "udp", new int[] {5, 20}, 200, 500);
        point(results, Scheme.DISTRIBUTED, "sim", new int[] {5, 20}, 70, 90);
        String shape = SetupTimeShape.describe(results);
        assertTrue(shape.indexOf("shape of the medians (sim):") < shape.indexOf("shape of the medians (udp):"), shape);
        String udp = shape.substring(shape.indexOf("(udp)"));
        assertTrue(udp.contains("centralised faster up to 5 roles, distributed from 20"), udp);
        String sim = shape.substring(0, shape.indexOf("(udp)"));
        assertTrue(!sim.contains("centralised"), "the sim runs had one scheme: " + sim);
    }

    @Test
    void faster_namesOneSchemeThroughout_orEveryPointWhenTheyCrossMoreThanOnceOrTie() {
        int[] roles = {5, 10, 20, 50};
        assertEquals("centralised faster at every number of roles (5 to 50)", SetupTimeShape.faster(List.of(5, 10, 20, 50),
                medians(roles, 80, 90, 100, 120), medians(roles, 30, 40, 60, 100)));
        assertEquals("distributed faster at every number of roles (5 to 50)", SetupTimeShape.faster(List.of(5, 10, 20, 50),
                medians(roles, 20, 30, 40, 50), medians(roles, 30, 40, 60, 100)));
        assertEquals("faster by the medians: centralised at 5, distributed at 10, centralised at 20, distributed at 50"
                        + " roles (the medians cross 3 times)",
                SetupTimeShape.faster(List.of(5, 10, 20, 50), medians(roles, 80, 30, 100, 50), medians(roles, 30, 40, 60, 100)));
        assertEquals("faster by the medians: centralised at 5, neither at 10, distributed at 20, distributed at 50 roles",
                SetupTimeShape.faster(List.of(5, 10, 20, 50), medians(roles, 80, 40, 50, 50), medians(roles, 30, 40, 60, 100)));
        assertEquals("", SetupTimeShape.faster(List.of(5), Map.of(5, 10.0), Map.of()), "no point both schemes have");
    }

    private static List<String> words(String line) {
        return List.of(line.strip().split("\\s+"));
    }
}
