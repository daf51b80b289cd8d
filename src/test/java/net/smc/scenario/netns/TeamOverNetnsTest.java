package net.smc.scenario.netns;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.stream.IntStream;

import net.smc.scenario.netns.NodeTeam.Event;
import net.smc.scenario.netns.NodeTeam.Node;
import net.smc.scenario.netns.NodeTeam.Vehicle;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The reconnaissance team as separate {@code smc node} processes, each in its own network namespace
 * on one bridge, over real UDP and authenticated: the behaviours {@code TeamScenariosTest} checks in
 * simulation, here with real processes, sockets, kills and cut links. Skipped, with the reason, where
 * a {@link NetnsLab} cannot be made (not root, no iproute2); the lossy formation is skipped, with the
 * reason, where no loss tool can be had.
 *
 * <p>The lossy formation uses the same vehicles as the first. Under loss the first surveyor may give
 * the second surveyor-capable vehicle a detector's or relay's seat before the commander reaches it;
 * the commander then moves it up to the vacant surveyor seat (see the team-protocols design note).
 *
 * <p>The measured times go to standard output, one {@code measured: ...} line each. On a failure,
 * the last lines of every node's log and the nodes' latest views are printed.
 */
@Timeout(value = 4, unit = TimeUnit.MINUTES)
class TeamOverNetnsTest {
    private static final Path PROJECT = Path.of(System.getProperty("smc.project.dir", ".")).toAbsolutePath();
    /** The mission's failureTimeout: a silent vehicle counts as failed after it. */
    private static final long FAILURE_MILLIS = 3_000;
    /**
     * A commander broadcasts its discovery beacon at least every 4 ticks of 500 ms; a free vehicle's
     * answer to it is how the commander knows the vehicle, and it gives a failed vehicle's seat at once
     * (Table II) only to one heard within the failure timeout; otherwise it finds one by discovery a
     * tick or two later. This is one beacon period and a tick to spare.
     */
    private static final Duration BEACON_PERIOD = Duration.ofMillis(2_500);
    /** How long any one phase may take. */
    private static final Duration PHASE = Duration.ofSeconds(30);

    /** The optimal team of the mission (Fig. 2): commander, two surveyors, an aggregator, two detectors, two relays. */
    private static final List<Vehicle> TEAM = List.of(Vehicle.commander("cdr"), Vehicle.surveyor("s1"), Vehicle.surveyor("s2"),
            Vehicle.aggregator("a1"), Vehicle.detector("d1"), Vehicle.detector("d2"), Vehicle.relay("r1"), Vehicle.relay("r2"));
    /** A surveyor-capable vehicle that joins the complete team, and so stays free: the spare. */
    private static final Vehicle SPARE = Vehicle.surveyor("s3");
    /** The optimal team again, for the formation under loss. */
    private static final List<Vehicle> LOSSY_TEAM = TEAM;

    @TempDir
    Path dir;

    private static void assumeLab() {
        Optional<String> reason = NetnsLab.unavailableReason();
        assumeTrue(reason.isEmpty(), () -> "no network namespace lab here: " + reason.orElseThrow());
    }

    private static List<String> ids(List<Vehicle> vehicles) {
        return vehicles.stream().map(Vehicle::id).toList();
    }

    private static long now() {
        return System.currentTimeMillis();
    }

    private static void measured(String line) {
        System.out.println("measured: " + line);
        System.out.flush();
    }

    /**
     * Forms the team; kills a surveyor and sees the spare take its seat; cuts the commander off, so that
     * its backup leads the rest as a team of its own, heals the cut and sees the two teams merge into one.
     */
    @Test
    void theTeamForms_replacesAKilledSurveyor_andMergesAfterTheCommanderIsCutOff() throws Exception {
        assumeLab();
        List<Vehicle> all = new ArrayList<>(TEAM);
        all.add(SPARE);
        try (NetnsLab lab = NetnsLab.create("smcteam", all.size() + 1)) {
            NodeTeam team = new NodeTeam(lab, dir, PROJECT, ids(all));
            try {
                team.startProbe(all.size(), IntStream.range(0, all.size()).boxed().toList());
                form(team);
                replaceAKilledSurveyor(team, all.size() - 1);
                mergeAfterTheCommanderIsCutOff(team, lab);
            } catch (Throwable t) {
                System.out.println(team.report());
                throw t;
            }
        }
    }

    /** The whole team starts at once, and the commander's mission runs, then reaches the optimal configuration. */
    private void form(NodeTeam team) throws Exception {
        long launched = now();
        List<Node> nodes = new ArrayList<>();
        for (int host = 0; host < TEAM.size(); host++) {
            nodes.add(team.start(host, TEAM.get(host)));
        }
        team.awaitUp(nodes);
        long up = now() - launched;
        team.awaitViews("the commander's mission running with two surveyors",
                v -> v.containsKey("cdr") && v.get("cdr").running() && v.get("cdr").count("surveyor") == 2, PHASE);
        Event running = team.awaitEvent(team.node("cdr"), "MISSION_STATE", "(RUNNING|OPTIMAL) .*", PHASE);
        team.awaitViews("the optimal configuration: every seat held by a vehicle of its own",
                v -> v.containsKey("cdr") && v.get("cdr").missionState().equals(Optional.of("OPTIMAL")), PHASE);
        Event optimal = team.awaitEvent(team.node("cdr"), "MISSION_STATE", "OPTIMAL .*", PHASE);
        measured("formation of " + TEAM.size() + " processes: all up " + up + " ms after launch; mission RUNNING "
                + (running.timeMillis() - launched) + " ms after launch, OPTIMAL " + (optimal.timeMillis() - launched) + " ms");
    }

    /** A free surveyor-capable vehicle joins; the holder of surveyor#1 is killed; the free one takes the seat. */
    private void replaceAKilledSurveyor(NodeTeam team, int spareHost) throws Exception {
        Node spare = team.start(spareHost, SPARE);
        team.awaitUp(List.of(spare));
        Map<String, NodeView> before = team.awaitViews("the spare up and free",
                v -> v.containsKey(SPARE.id()) && v.get(SPARE.id()).roles().isEmpty(), PHASE);
        Thread.sleep(BEACON_PERIOD.toMillis());
        String victimId = before.values().stream().filter(v -> v.roles().contains("surveyor#1")).map(NodeView::vehicle)
                .findFirst().orElseThrow(() -> new AssertionError("no one holds surveyor#1: " + before));
        Node victim = team.node(victimId);

        long killedAt = now();
        team.kill(victim);
        Event accepted = team.awaitEvent(spare, "ACCEPTED", "surveyor#1 .* from cdr, .*", PHASE);
        long replaced = accepted.timeMillis() - killedAt;

        Event failure = team.awaitEvent(team.node("cdr"), "FAILURE", victimId + " silent for .*", PHASE);
        assertTrue(replaced > 0 && replaced <= 3 * FAILURE_MILLIS, "the spare took surveyor#1 " + replaced
                + " ms after the kill; expected within three failure timeouts, as in the simulation");
        boolean direct = team.events(team.node("cdr")).stream().anyMatch(e -> e.kind().equals("REASSIGNING")
                && e.detail().matches("surveyor#1 .* to free vehicle " + SPARE.id()));
        List<String> orphans = before.values().stream().filter(v -> v.parent().equals(Optional.of(victimId)))
                .map(NodeView::vehicle).toList();
        Map<String, NodeView> after = team.awaitViews("the optimal configuration again: the spare surveys, and "
                + orphans + " of " + victimId + " re-attached to it", v -> v.containsKey("cdr")
                && v.get("cdr").missionState().equals(Optional.of("OPTIMAL"))
                && orphans.stream().allMatch(o -> v.containsKey(o) && v.get(o).parent().equals(Optional.of(SPARE.id()))), PHASE);
        long recovered = now() - killedAt;
        assertEquals(Optional.of("cdr"), after.get(SPARE.id()).parent(), after.get(SPARE.id()).json());
        measured("kill to replacement: " + victimId + " (surveyor#1) killed; commander saw the failure after "
                + (failure.timeMillis() - killedAt) + " ms; " + SPARE.id() + " ACCEPTED surveyor#1 after " + replaced
                + " ms (" + (direct ? "re-assigned to it as a free vehicle" : "found by discovery") + "); OPTIMAL again within "
                + recovered + " ms");
    }

    /**
     * The commander's host is cut off: its first backup takes over and leads the commander's other
     * children, while the commander, alone, still acts. On healing they meet, the commander of the
     * lower epoch steps down, and one tree remains.
     */
    private void mergeAfterTheCommanderIsCutOff(NodeTeam team, NetnsLab lab) throws Exception {
        Node cdr = team.node("cdr");
        Map<String, NodeView> before = team.views();
        List<Node> others = team.alive().stream().filter(n -> n != cdr).toList();

        long cutAt = now();
        lab.cut(cdr.host());
        Event tookOver = team.awaitAnyEvent(others, "TOOK_OVER", PHASE);
        String backup = tookOver.vehicle();
        List<String> formerChildren = before.values().stream().filter(v -> v.parent().equals(Optional.of("cdr")))
                .map(NodeView::vehicle).filter(id -> !id.equals(backup)).toList();
        // Each adopts the backup when its status reaches it, or, should its lease from cdr run out first, joins it anew.
        team.awaitViews("the backup " + backup + " leading " + formerChildren + ", the other children of cdr",
                v -> v.containsKey(backup) && v.get(backup).acting() && formerChildren.stream()
                        .allMatch(c -> v.containsKey(c) && v.get(c).parent().equals(Optional.of(backup))), PHASE);
        long adopted = formerChildren.stream().filter(c -> eventsOf(team, c).stream().anyMatch(e -> e.kind().equals("ADOPTED")
                && e.detail().startsWith("new commander " + backup + " "))).count();
        team.awaitEvent(cdr, "FAILURE", backup + " silent for .*", PHASE);
        assertTrue(team.events(cdr).stream().noneMatch(e -> e.kind().equals("STEPPED_DOWN")),
                "the commander, cut off, still leads its own team");

        long healedAt = now();
        lab.heal(cdr.host());
        Event steppedDown = team.awaitEvent(cdr, "STEPPED_DOWN", "meets commander " + backup + " of epoch 1 .*", PHASE);
        List<String> alive = team.alive().stream().map(Node::id).toList();
        Map<String, NodeView> merged = team.awaitViews("one tree: exactly one acting commander, and every vehicle with "
                + "a role linked to it through its parents", v -> oneTree(v, alive), PHASE);
        long treeAt = now();
        assertEquals(List.of(backup), merged.values().stream().filter(NodeView::acting).map(NodeView::vehicle).toList(),
                "the commander of the higher epoch leads the merged team");
        measured("partition and merge: cdr cut off; " + backup + " TOOK_OVER after " + (tookOver.timeMillis() - cutAt)
                + " ms (" + adopted + " of the " + formerChildren.size() + " other children adopted it); after healing, "
                + "one commander after " + (steppedDown.timeMillis() - healedAt) + " ms (cdr STEPPED_DOWN), one tree within "
                + (treeAt - healedAt) + " ms");
    }

    private static List<Event> eventsOf(NodeTeam team, String id) {
        try {
            return team.events(team.node(id));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Whether every node of {@code alive} answered, exactly one acts as commander, and every node with
     * a role reaches that commander through its parents, none suspended.
     */
    static boolean oneTree(Map<String, NodeView> views, List<String> alive) {
        if (!views.keySet().containsAll(alive)) {
            return false;
        }
        List<NodeView> acting = views.values().stream().filter(NodeView::acting).toList();
        if (acting.size() != 1) {
            return false;
        }
        String commander = acting.get(0).vehicle();
        for (NodeView view : views.values()) {
            if (view.roles().isEmpty() || view.acting()) {
                continue;
            }
            NodeView at = view;
            for (int hops = 0; at != null && !at.acting(); hops++) {
                if (at.suspended() || at.parent().isEmpty() || hops > views.size()) {
                    return false;
                }
                at = views.get(at.parent().get());
            }
            if (at == null || !at.vehicle().equals(commander)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The whole team starts at once with every host dropping 20% of the packets it receives, and still
     * forms: exactly one acting commander, whose mission runs with two surveyors. (Loss may make the
     * backup take over from a live commander, which then steps down: the line reports it.)
     */
    @Test
    void theTeamFormsWithTwentyPercentLossOnEveryHost() throws Exception {
        assumeLab();
        Optional<String> noLoss = NetnsLab.ensureLossTool();
        assumeTrue(noLoss.isEmpty(), () -> "no packet loss can be set here: " + noLoss.orElseThrow());
        try (NetnsLab lab = NetnsLab.create("smcloss", LOSSY_TEAM.size() + 1)) {
            NodeTeam team = new NodeTeam(lab, dir, PROJECT, ids(LOSSY_TEAM));
            try {
                for (int host = 0; host < LOSSY_TEAM.size(); host++) {
                    lab.loss(host, 20);
                }
                team.startProbe(LOSSY_TEAM.size(), IntStream.range(0, LOSSY_TEAM.size()).boxed().toList());
                long launched = now();
                List<Node> nodes = new ArrayList<>();
                for (int host = 0; host < LOSSY_TEAM.size(); host++) {
                    nodes.add(team.start(host, LOSSY_TEAM.get(host)));
                }
                team.awaitUp(nodes);
                long up = now() - launched;
                Map<String, NodeView> formed = team.awaitViews("one acting commander whose mission runs with two surveyors, "
                        + "under 20% loss", TeamOverNetnsTest::runsUnderOneCommander, PHASE.plus(PHASE));
                long runningAt = now() - launched;
                String commander = formed.values().stream().filter(NodeView::acting).findFirst().orElseThrow().vehicle();
                List<Event> events = new ArrayList<>();
                for (Node node : nodes) {
                    events.addAll(team.events(node));
                }
                measured("formation of " + LOSSY_TEAM.size() + " processes under 20% loss on every host: all up " + up
                        + " ms after launch; one commander (" + commander + ") running with two surveyors seen within "
                        + runningAt + " ms of launch; " + count(events, "TOOK_OVER") + " take-overs, "
                        + count(events, "SUSPENDED") + " suspended leases, " + count(events, "ORPHANED") + " orphaned on the way");
            } catch (Throwable t) {
                System.out.println(team.report());
                throw t;
            }
        }
    }

    private static boolean runsUnderOneCommander(Map<String, NodeView> views) {
        List<NodeView> acting = views.values().stream().filter(NodeView::acting).toList();
        return acting.size() == 1 && acting.get(0).running() && acting.get(0).count("surveyor") == 2;
    }

    private static long count(List<Event> events, String kind) {
        return events.stream().filter(e -> e.kind().equals(kind)).count();
    }
}
