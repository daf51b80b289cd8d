package net.smc.sim.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.TreeMap;

import org.junit.jupiter.api.Test;

/**
 * The invariant checks' walks over the parent links: cycles found and named, teams as the walk up
 * through live leases and listing parents defines them, and each parent asked once per child.
 */
class ParentLinksTest {
    /** A stand-in cell: its parent, whether it commands, whether its lease ran out, the children it lists. */
    private record Node(String vehicle, String parent, boolean acting, boolean suspended, Set<String> children) {
    }

    private int asked;

    private ParentLinks<Node> links(List<Node> nodes) {
        return new ParentLinks<>(nodes, Node::vehicle, Node::parent, Node::acting, Node::suspended, (n, v) -> {
            asked++;
            return n.children().contains(v);
        });
    }

    private static Node node(String vehicle, String parent, String... children) {
        return new Node(vehicle, parent, false, false, Set.of(children));
    }

    @Test
    void aTreeHasNoCycle_andEveryListedLeasedCellIsInItsCommandersTeam() {
        List<Node> nodes = List.of(new Node("cdr", null, true, false, Set.of("a", "b")), node("a", "cdr", "c"),
                node("b", "cdr"), node("c", "a"), node("d", "b"),            // d: b does not list it
                new Node("e", "a", false, true, Set.of()), node("f", "gone"));  // e: suspended; f: its parent is not live
        ParentLinks<Node> l = links(nodes);
        assertNull(l.cycle());
        Map<String, List<Node>> teams = l.teams();
        assertEquals(List.of("cdr", "a", "b", "c"), teams.get("cdr").stream().map(Node::vehicle).toList());
        assertEquals(1, teams.size());
        assertFalse(l.listedByParent(3 + 1));
        assertFalse(l.listedByParent(6));
        assertTrue(l.listedByParent(3));
    }

    @Test
    void aCycleIsFoundAndNamed() {
        List<Node> nodes = List.of(node("x", null), node("a", "c", "b"), node("b", "a", "c"), node("c", "b", "a"), node("d", "a"));
        Set<String> cycle = links(nodes).cycle();
        assertTrue(cycle != null && cycle.containsAll(Set.of("a", "b", "c")), String.valueOf(cycle));
        // Listed all the way round but never reaching a commander: no team.
        assertTrue(links(nodes).teams().isEmpty());
    }

    @Test
    void aChainLongerThanTheWalkLimitIsNotAttached() {
        List<Node> nodes = new ArrayList<>();
        nodes.add(new Node("n0", null, true, false, Set.of("n1")));
        for (int i = 1; i <= ParentLinks.ROOT_WALK_LIMIT + 1; i++) {
            nodes.add(node("n" + i, "n" + (i - 1), "n" + (i + 1)));
        }
        Map<String, List<Node>> teams = links(nodes).teams();
        // n0 (0 steps) to n63 (63 steps) are attached; n64 and n65 are not.
        assertEquals(ParentLinks.ROOT_WALK_LIMIT, teams.get("n0").size());
    }

    /** Random forests with cycles, suspensions and unlisted children: the teams a direct walk from each cell finds. */
    @Test
    void teamsAreThoseOfADirectWalkFromEachCell_askingEachParentOncePerChild() {
        Random random = new Random(7);
        for (int round = 0; round < 300; round++) {
            int n = 1 + random.nextInt(40);
            List<Node> nodes = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                String parent = random.nextInt(6) == 0 ? null : random.nextInt(12) == 0 ? "gone" : "v" + random.nextInt(n);
                Set<String> children = new HashSet<>();
                for (int k = 0; k < n; k++) {
                    if (random.nextInt(3) != 0) {
                        children.add("v" + k);
                    }
                }
                nodes.add(new Node("v" + i, parent, random.nextInt(8) == 0, random.nextInt(10) == 0, children));
            }
            asked = 0;
            ParentLinks<Node> l = links(nodes);
            Map<String, List<String>> teams = new TreeMap<>();
            l.teams().forEach((k, v) -> teams.put(k, v.stream().map(Node::vehicle).toList()));
            assertEquals(directTeams(nodes), teams, "round " + round + ": " + nodes);
            assertTrue(asked <= n, "asked " + asked + " times for " + n + " cells");
            assertEquals(directCycle(nodes), l.cycle() != null, "round " + round + ": " + nodes);
        }
    }

    /** The definition, walked from each cell on its own. */
    private static Map<String, List<String>> directTeams(List<Node> nodes) {
        Map<String, Node> byId = new TreeMap<>();
        nodes.forEach(n -> byId.put(n.vehicle(), n));
        Map<String, List<String>> teams = new TreeMap<>();
        for (Node start : nodes) {
            Node at = start;
            for (int steps = 0; steps < ParentLinks.ROOT_WALK_LIMIT; steps++) {
                if (at.acting()) {
                    teams.computeIfAbsent(at.vehicle(), k -> new ArrayList<>()).add(start.vehicle());
                    break;
                }
                Node p = at.suspended() || at.parent() == null ? null : byId.get(at.parent());
                if (p == null || !p.children().contains(at.vehicle())) {
                    break;
                }
                at = p;
            }
        }
        return teams;
    }

    private static boolean directCycle(List<Node> nodes) {
        Map<String, Node> byId = new TreeMap<>();
        nodes.forEach(n -> byId.put(n.vehicle(), n));
        for (Node start : nodes) {
            Node at = start;
            for (int steps = 0; steps <= nodes.size(); steps++) {
                at = at.parent() == null ? null : byId.get(at.parent());
                if (at == null) {
                    break;
                }
                if (at == start) {
                    return true;
                }
            }
        }
        return false;
    }
}
