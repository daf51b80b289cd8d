package net.smc.sim.team;

import net.smc.core.host.CellHost;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;
import java.util.function.Predicate;
import java.util.stream.Stream;

import net.smc.core.cell.Cell;
import net.smc.core.host.CellHost;
import net.smc.core.cell.CellView;
import net.smc.core.cell.MissionState;
import net.smc.core.cell.Missions;
import net.smc.core.mission.Mission;
import net.smc.core.transport.udp.UdpEventLoop;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * The team scenarios of {@link TeamScenariosTest} on Netty UDP over loopback: every vehicle a
 * {@link CellHost} with its own thread, its own unicast port on 127.0.0.1 and its team's broadcast
 * port, all on one shared event loop ({@link UdpTeam}). The reconnaissance team forms the tree of
 * figure 5 (with and without real authentication) or, under the centralised scheme, a flat tree; a
 * crashed surveyor is replaced by a spare that receives the state it reported (also with 10% of the
 * datagrams lost once the team has formed); a crashed commander is replaced by its backup in epoch
 * 1; the parts of a partition that heals merge under one commander. The safety invariants are
 * checked on the cells' views at every poll, and each scenario waits for the team to settle as
 * {@code TeamInvariants} defines it.
 *
 * <p>Real time cannot be sped up and a recovery takes a failure timeout (3 s) and more, so the
 * runs go concurrently: the factory starts them all, each team on a broadcast port of its own
 * (teams cannot hear each other), and each dynamic test waits for one run's outcome. Bounds are
 * generous liveness bounds; the figures themselves are {@code FormationTiming}'s.
 */
class TeamOverUdpTest {
    private static final long FAILURE = 3_000;
    private static final long[] SEEDS = {1, 2};
    /** A run that has not ended by then hangs: each takes about 20 s at most. */
    private static final long HANG_GUARD_SECONDS = 120;

    private static UdpEventLoop loop;
    private static ExecutorService runs;

    @BeforeAll
    static void open() {
        loop = UdpEventLoop.create(2);
        runs = Executors.newCachedThreadPool(r -> {
            Thread t = new Thread(r, "udp-team-run");
            t.setDaemon(true);
            return t;
        });
    }

    @AfterAll
    static void close() {
        runs.shutdownNow();
        loop.close();
    }

    @TestFactory
    Stream<DynamicTest> teamScenariosOnLoopbackUdp() {
        List<DynamicTest> tests = new ArrayList<>();
        for (long seed : SEEDS) {
            tests.add(run("the team forms the tree of figure 5", seed, Missions.reconnaissance(), false,
                    TeamOverUdpTest::formsTheTreeOfFigureFive));
            tests.add(run("authenticated cells form the same team", seed, Missions.reconnaissance(), true,
                    TeamOverUdpTest::formsTheTreeOfFigureFive));
            tests.add(run("the centralised scheme forms a flat tree", seed, Missions.centralised(), false,
                    TeamOverUdpTest::formsAFlatTree));
            tests.add(run("a crashed surveyor is replaced by the spare, which receives its state", seed,
                    Missions.reconnaissance(), false, team -> crashedSurveyorIsReplacedBySpare(team, seed, 0)));
            tests.add(run("the backup takes over from a crashed commander", seed, Missions.reconnaissance(), false,
                    TeamOverUdpTest::backupTakesOverFromCrashedCommander));
            tests.add(run("partitioned parts merge into one team when the partition heals", seed,
                    Missions.reconnaissance(), false, TeamOverUdpTest::partsMergeWhenThePartitionHeals));
        }
        tests.add(run("with 10% of datagrams lost from the start, the team still forms", 4, Missions.reconnaissance(),
                false, team -> {
                    team.loss(0.1);
                    formsTheTreeOfFigureFive(team);
                }));
        tests.add(run("with 10% of datagrams lost, a crashed surveyor is still replaced by the spare", 3,
                Missions.reconnaissance(), false, team -> crashedSurveyorIsReplacedBySpare(team, 3, 0.1)));
        return tests.stream();
    }

    /** Starts one run now; its test waits for the outcome. */
    private static DynamicTest run(String name, long seed, Mission mission, boolean secure, Consumer<UdpTeam> scenario) {
        CompletableFuture<Void> outcome = CompletableFuture.runAsync(() -> {
            try (UdpTeam team = new UdpTeam(mission, seed, secure, loop)) {
                scenario.accept(team);
            }
        }, runs);
        return dynamicTest(name + " (seed " + seed + ")", () -> {
            try {
                outcome.get(HANG_GUARD_SECONDS, TimeUnit.SECONDS);
            } catch (ExecutionException e) {
                if (e.getCause() instanceof AssertionError a) {
                    throw a;
                }
                throw new AssertionError("the run failed: " + e.getCause(), e.getCause());
            } catch (TimeoutException e) {
                throw new AssertionError("the run did not end within " + HANG_GUARD_SECONDS + " s", e);
            }
        });
    }

    // ---------------------------------------------------------------- scenarios

    private static void formsTheTreeOfFigureFive(UdpTeam team) {
        team.start(SimVehicle.reconnaissance(2, 1, 2, 2));
        settle(team, "the optimal configuration in the tree of figure 5", 5 * FAILURE,
                views -> state(views, "cdr") == MissionState.OPTIMAL
                        && views.get("cdr").children().keySet().equals(Set.of("s1", "s2", "a1"))
                        && views.get("s1").children().size() == 2 && views.get("s2").children().size() == 2);
    }

    private static void formsAFlatTree(UdpTeam team) {
        team.start(SimVehicle.reconnaissance(2, 1, 2, 2));
        settle(team, "the optimal configuration in a flat tree", 5 * FAILURE,
                views -> state(views, "cdr") == MissionState.OPTIMAL && views.get("cdr").children().size() == 7
                        && views.values().stream().allMatch(v -> v.acting() || v.children().isEmpty()));
    }

    /**
     * After formation (loss, if any, starts then), a spare surveyor joins and one surveyor reports a
     * position, then crashes. Reports repeat every fourth heartbeat (2 s), so 5 s carry the position
     * to the commander despite a lost report or two.
     */
    private static void crashedSurveyorIsReplacedBySpare(UdpTeam team, long seed, double loss) {
        team.start(SimVehicle.reconnaissance(2, 1, 2, 2));
        settle(team, "the optimal configuration", 5 * FAILURE, v -> state(v, "cdr") == MissionState.OPTIMAL);
        team.loss(loss);
        team.join(SimVehicle.surveyor("s3"));
        String crashed = seed % 2 == 0 ? "s2" : "s1";
        List<Object> position = List.of(new BigDecimal("12.5"), BigDecimal.valueOf(-3 - seed));
        team.call(crashed, cell -> {
            cell.reportState(position);
            return null;
        });
        team.hold(5_000);
        assertTrue(team.views().get("s3").roles().isEmpty(), "s3 is a spare");
        team.crash(crashed);
        team.await("s3 taking the surveyor role", 3 * FAILURE, views -> UdpTeam.holds(views, "s3", "surveyor"));
        assertEquals(position, team.call("s3", Cell::handedOver), "s3 received what " + crashed + " reported");
        settle(team, "the orphaned detector and relay re-attached to s3", 4 * FAILURE,
                views -> views.get("s3").children().size() == 2);
    }

    private static void backupTakesOverFromCrashedCommander(UdpTeam team) {
        team.start(SimVehicle.reconnaissance(2, 1, 2, 2));
        settle(team, "the optimal configuration", 5 * FAILURE, v -> state(v, "cdr") == MissionState.OPTIMAL);
        team.hold(FAILURE);   // the roster reaches the backup
        String backup = backup(team, team.views(), "cdr");
        team.crash("cdr");
        Map<String, CellView> views = team.await("an acting commander", 3 * FAILURE,
                v -> !UdpTeam.commanders(v).isEmpty());
        assertEquals(List.of(backup), UdpTeam.commanders(views), "the backup took over, and it alone");
        assertEquals(1, views.get(backup).epoch());
        settle(team, "the team under " + backup, 6 * FAILURE, v -> true);
    }

    /**
     * The backup, its detector and relay, and the aggregator are cut off from the rest. Every vehicle
     * holds a seat when the cut comes, so no manager has a free vehicle to assign across it. The
     * backup takes over its part in epoch 1; when the cut heals, the commander of epoch 0 steps down
     * and its vehicles join the team of epoch 1.
     */
    private static void partsMergeWhenThePartitionHeals(UdpTeam team) {
        team.start(SimVehicle.reconnaissance(2, 1, 2, 2));
        settle(team, "the optimal configuration", 5 * FAILURE, v -> state(v, "cdr") == MissionState.OPTIMAL);
        team.hold(FAILURE);   // the roster reaches the backup
        Map<String, CellView> formed = team.views();
        String backup = backup(team, formed, "cdr");
        Set<String> side = new TreeSet<>(formed.get(backup).children().keySet());
        side.addAll(List.of(backup, "a1"));
        team.partition(side);
        team.await("a commander in each part", 4 * FAILURE,
                views -> Set.copyOf(UdpTeam.commanders(views)).equals(Set.of("cdr", backup)));
        team.hold(FAILURE);
        team.heal();
        Map<String, CellView> merged = settle(team, "one merged team", 8 * FAILURE,
                views -> UdpTeam.commanders(views).equals(List.of(backup)));
        assertEquals(1, merged.get(backup).epoch());
        merged.values().forEach(v -> assertTrue(v.acting() || v.parent() != null || v.roles().isEmpty(),
                v.vehicle() + " hangs loose: " + v.toJson()));
    }

    // ---------------------------------------------------------------- helpers

    /** Waits until the team has settled (one commander, the best configuration) and {@code also} holds. */
    private static Map<String, CellView> settle(UdpTeam team, String what, long maxMillis,
                                                Predicate<Map<String, CellView>> also) {
        return team.await(what + ", settled", maxMillis, views -> team.unsettled(views).isEmpty() && also.test(views));
    }

    private static MissionState state(Map<String, CellView> views, String commander) {
        CellView v = views.get(commander);
        return v == null ? null : v.state();
    }

    /**
     * The commander's first backup, by the protocol's rule: of its children able to command, the one
     * whose seat comes first in the identity sequence.
     */
    private static String backup(UdpTeam team, Map<String, CellView> views, String commander) {
        return views.get(commander).children().keySet().stream().filter(team::ableToCommand).map(views::get)
                .min(Comparator.comparingInt(TeamOverUdpTest::sequence)).map(CellView::vehicle)
                .orElseThrow(() -> new AssertionError(commander + " has no child able to command: " + views));
    }

    /** The sequence number of a view's identity, {@code [mission|level|sequence]}. */
    private static int sequence(CellView v) {
        String id = v.identity();
        return Integer.parseInt(id.substring(id.lastIndexOf('|') + 1, id.length() - 1));
    }
}
