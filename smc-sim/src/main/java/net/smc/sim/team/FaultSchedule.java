package net.smc.sim.team;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.function.Consumer;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Scheme;
import net.smc.core.mission.Mission;
import net.smc.core.transport.sim.LinkProfile;
import net.smc.policy.api.PolicyRepository;

/**
 * One seeded run of a reconnaissance team under faults: the seed picks the team (4 to 13
 * vehicles, sometimes a rogue), the scheme, the links (loss up to 30%, duplication, re-ordering,
 * delay within the protocols' latency assumption), on every tenth seed an {@link Adversary}, and a schedule of faults (crashes and restarts,
 * partitions and heals, leaves and re-joins, new vehicles, link changes). After the faults stop,
 * the team must settle within {@link #settleBoundMillis}.
 *
 * <p>{@link #run()} throws {@link InvariantViolation} at the first broken invariant, or when the
 * team does not settle in time; either way the message names the seed, and running the same seed
 * replays the same run.
 */
public final class FaultSchedule {
    private final Mission distributed;
    private final Mission centralised;
    private final PolicyRepository repository;
    private final long seed;
    private final long faultMillis;
    private Consumer<String> log = line -> { };
    private Consumer<CellEvent> events = e -> { };
    private boolean adversary;
    private boolean verifyReadings;

    /**
     * @param distributed the reconnaissance mission, distributed scheme
     * @param centralised the same mission, centralised scheme
     * @param faultMillis how long faults go on (simulated ms)
     */
    public FaultSchedule(Mission distributed, Mission centralised, PolicyRepository repository, long seed, long faultMillis) {
        this.distributed = distributed;
        this.centralised = centralised;
        this.repository = repository;
        this.seed = seed;
        this.faultMillis = faultMillis;
        this.adversary = hasAdversary(seed);
    }

    /** Puts an {@link Adversary} on the channel, or takes it off (by default: {@link #hasAdversary}). */
    public FaultSchedule adversary(boolean on) {
        this.adversary = on;
        return this;
    }

    /** Makes every invariant check verify its incremental readings ({@link TeamSimulationBuilder#verifyInvariantReadings}). */
    public FaultSchedule verifyInvariantReadings(boolean on) {
        this.verifyReadings = on;
        return this;
    }

    /** Receives a line per fault applied. */
    public FaultSchedule log(Consumer<String> log) {
        this.log = log;
        return this;
    }

    /** Receives every event of the run (each cell's decisions and the faults applied), in order. */
    public FaultSchedule events(Consumer<CellEvent> events) {
        this.events = events;
        return this;
    }

    /**
     * The time the team gets to settle once faults stop, from the mission's timeouts: long enough
     * for orphans to drop their roles ({@code failureTimeout + (backups + 2) * comTimeout}) twice
     * over (a take-over and then a merge), for two beaconing commanders to meet under loss, and for
     * rediscovery and assignment: {@code 3 * orphan + 40 * comTimeout}.
     */
    public static long settleBoundMillis(Mission mission) {
        net.smc.core.cell.Timing t = net.smc.core.cell.Timing.of(mission);
        return 3 * t.orphanMillis() + 40 * t.comTimeoutMillis();
    }

    /**
     * Whether the run of {@code seed} has an {@link Adversary} on the channel: every tenth seed (so
     * the sweep's cost barely grows). Its datagrams are drawn from its own random source, so a run's
     * faults and links are those of the same seed without it.
     */
    public static boolean hasAdversary(long seed) {
        return seed % 10 == 0;
    }

    /** What the run did, for reports. */
    /**
     * @param matchesPlan whether the settled team is exactly what the planner gives (see
     *                    {@link TeamInvariants#matchesPlan()})
     */
    public record Outcome(long seed, int vehicles, Scheme scheme, int faults, long settledAfterMillis, long checks,
                          boolean matchesPlan) {
    }

    public Outcome run() {
        SplittableRandom random = new SplittableRandom(seed);
        boolean flat = random.nextInt(10) < 3;
        Mission mission = flat ? centralised : distributed;
        List<SimVehicle> team = new ArrayList<>(SimVehicle.reconnaissance(2 + random.nextInt(3), 1 + random.nextInt(2),
                random.nextInt(4), random.nextInt(4)));
        if (random.nextInt(4) == 0) {
            team.add(SimVehicle.surveyor("rogue").asRogue());
        }
        if (random.nextInt(8) == 0) {
            team.add(SimVehicle.command("rcdr").asCommander().asRogue());
        }
        TeamSimulation sim = TeamSimulation.builder(mission, repository, seed).vehicles(team).link(link(random))
                .listener(events).adversary(adversary).verifyInvariantReadings(verifyReadings).build();
        sim.start();
        List<String> honest = team.stream().filter(v -> !v.rogue()).map(SimVehicle::id).toList();
        List<String> crashed = new ArrayList<>();
        List<String> away = new ArrayList<>();
        int joined = 0;
        int faults = 0;
        sim.run(2_000 + random.nextInt(6_000));
        long end = sim.nowMillis() + faultMillis;
        while (sim.nowMillis() < end) {
            faults++;
            int kind = random.nextInt(10);
            String v = honest.get(random.nextInt(honest.size()));
            switch (kind) {
                case 0, 1 -> {
                    if (sim.isLive(v) && (!v.equals("cdr") || random.nextInt(3) == 0)) {
                        note(sim, "crash " + v);
                        sim.crash(v);
                        crashed.add(v);
                    }
                }
                case 2 -> {
                    if (!crashed.isEmpty()) {
                        String back = crashed.remove(random.nextInt(crashed.size()));
                        note(sim, "restart " + back);
                        sim.restart(back);
                    }
                }
                case 3 -> {
                    List<String> side = new ArrayList<>();
                    for (SimVehicle x : sim.vehicles()) {
                        if (random.nextBoolean()) {
                            side.add(x.id());
                        }
                    }
                    if (!side.isEmpty() && side.size() < sim.vehicles().size()) {
                        note(sim, "partition " + side);
                        sim.partition(side);
                    }
                }
                case 4 -> {
                    note(sim, "heal");
                    sim.heal();
                }
                case 5 -> {
                    if (sim.isLive(v) && !v.equals("cdr") && !away.contains(v)) {
                        note(sim, "leave " + v);
                        sim.leave(v);
                        away.add(v);
                    } else if (!away.isEmpty()) {
                        String back = away.remove(0);
                        note(sim, "rejoin " + back);
                        sim.rejoin(back);
                    }
                }
                case 6 -> {
                    if (joined < 3) {
                        joined++;
                        SimVehicle n = switch (random.nextInt(3)) {
                            case 0 -> SimVehicle.surveyor("ns" + joined);
                            case 1 -> SimVehicle.detector("nd" + joined);
                            default -> SimVehicle.relay("nr" + joined);
                        };
                        note(sim, "join " + n.id());
                        sim.join(n);
                        honest = new ArrayList<>(honest);
                        honest.add(n.id());
                    }
                }
                default -> {
                    LinkProfile p = link(random);
                    note(sim, "links " + p);
                    sim.link(p);
                }
            }
            sim.run(500 + random.nextInt(4_000));
        }
        note(sim, "faults stop");
        sim.heal();
        for (String back : away) {
            sim.rejoin(back);
        }
        long stopped = sim.nowMillis();
        long bound = settleBoundMillis(mission);
        boolean settled = sim.runUntil(() -> sim.invariants().settledOrDissolved(), bound);
        if (!settled) {
            List<String> lines = new ArrayList<>(sim.trace());
            lines.add("--- views at the end");
            sim.cells().forEach(c -> lines.add(c.view().toJson()));
            throw new InvariantViolation("the team did not settle within " + bound + " ms after the faults stopped: "
                    + sim.invariants().unsettled(), seed, sim.nowMillis(), lines);
        }
        boolean dissolved = sim.commanders().isEmpty();
        return new Outcome(seed, team.size() + joined, flat ? Scheme.CENTRALISED : Scheme.DISTRIBUTED, faults,
                sim.nowMillis() - stopped, sim.invariants().checks(), !dissolved && sim.invariants().matchesPlan());
    }

    private void note(TeamSimulation sim, String what) {
        sim.record(new CellEvent(sim.nowMillis(), "-", CellEvent.Kind.LEFT, "*** " + what));
        log.accept(sim.nowMillis() + " " + what);
    }

    /** Loss up to 30%, duplication and re-ordering up to 10%, one-way delay at most 5 + 60 + 60 ms. */
    private static LinkProfile link(SplittableRandom random) {
        return new LinkProfile(1 + random.nextInt(5), random.nextInt(60), random.nextDouble() * 0.3,
                random.nextDouble() * 0.1, random.nextDouble() * 0.1, 1 + random.nextInt(60));
    }
}
