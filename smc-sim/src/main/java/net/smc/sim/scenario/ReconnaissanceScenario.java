package net.smc.sim.scenario;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;

import net.smc.core.cell.Cell;
import net.smc.core.cell.CellEvent;
import net.smc.core.mission.MissionException;
import net.smc.core.transport.sim.LinkProfile;
import net.smc.policy.api.AuthMode;
import net.smc.sim.arena.Arena;
import net.smc.sim.arena.ArenaException;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.radio.RadioSettings;
import net.smc.sim.render.GifRecorder;
import net.smc.sim.render.Mark;
import net.smc.sim.render.RoleLabels;
import net.smc.sim.render.Scene;
import net.smc.sim.render.Timeline;
import net.smc.sim.render.TrajectoryRecorder;
import net.smc.sim.render.WorldPainter;
import net.smc.sim.robot.KoalaSpec;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.task.Aggregator;
import net.smc.sim.team.SimVehicle;
import net.smc.sim.team.TeamSimulation;
import net.smc.sim.team.WorldTeam;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.WorldStepListener;

/**
 * The reconnaissance of the paper's section II-A run by cells and policies in the simulated house
 * ({@code missions/worlds/house.xml}): is the house safe for people to enter? The commander's
 * laptop ({@code cdr}) waits at its station; eight Koala-like robots enter one by one at the
 * entrance: two surveyors, the aggregator (minimal configuration, Fig. 1: each surveyor also holds
 * the hazard-detector and relay roles), two detectors and two relays (reasonably-optimal, Fig. 2),
 * then, after one detector's battery has died and the team has contracted, a third robot able to
 * survey and detect. The mission {@code missions/reconnaissance-house.instance.xml} decides
 * everything else: surveyors explore and keep away from suspected hazards, detectors confirm them,
 * the aggregator merges the maps and the hazards into the hazard map.
 *
 * <p>The scenario only powers the robots on at their times and drains the battery; it watches the
 * team's configuration (a timeline row for each change), the aggregator's map (the share of the
 * free floor it knows, {@link FloorCoverage}) and its hazards. The goal: at least
 * {@link ReconnaissanceSettings#coverageGoal} of the free floor on the aggregator's map and every hazard of the
 * house on it (within {@link #FOUND_WITHIN} of its centre, of its kind).
 *
 * <pre>{@code
 * ReconnaissanceScenario recon = ReconnaissanceScenario.load(Path.of("."), ReconnaissanceSettings.of(7), row -> { });
 * ReconnaissanceOutcome outcome = recon.run();   // outcome.succeeded(), recon.timeline() ...
 * }</pre>
 */
public final class ReconnaissanceScenario {
    /** How close a hazard on the aggregator's map must be to a real one (of its kind) to count it found, metres. */
    public static final double FOUND_WITHIN = 1.5;
    /** The house's radio: light interior walls (each keeps 95% of a link's quality) over 60 m. */
    public static final RadioSettings HOUSE_RADIO = new RadioSettings(60, 0.95, 0.1, true);

    /**
     * The house's robots: Koalas whose ring of proximity sensors reaches 2 m from the body (the
     * Koala's own infrared reaches 0.2 m): a modelling choice, so that two surveyors map the house
     * in minutes rather than hours. Their odometry is the Koala's, corrected by a position fix
     * every {@link #FIX_EVERY_STEPS} world steps (see {@link SimRobot#positionFix()}).
     */
    public static final KoalaSpec HOUSE_ROBOT = KoalaSpec.koala().withIrRange(2.0);
    /**
     * World steps between two position fixes of every robot (1 s at 20 ms): the house has
     * positioning beacons, since the tasks do no localisation of their own and wheels slip on
     * every bump, which would put the map and the hazards metres from where they are.
     */
    public static final int FIX_EVERY_STEPS = 50;
    /** World steps between two looks at the hazard map (0.2 s): its coverage and hazards. */
    private static final int WATCH_EVERY_STEPS = 10;

    private final ReconnaissanceSettings settings;
    private final TeamSimulation team;
    private final WorldTeam world;
    private final Arena arena;
    private final List<Arrival> arrivals;
    private final String failing;
    private final FloorCoverage floor;
    private final ScenarioLog log;
    private final TrajectoryRecorder tracks = new TrajectoryRecorder(10);
    private final Scene scene = new Scene("Reconnaissance of the house (cf. the paper's Fig. 1 and 2)");
    private final Map<String, String> labels = new LinkedHashMap<>();
    private final GifRecorder film;
    private final List<String> standings = new ArrayList<>();
    private final List<String> found = new ArrayList<>();
    private int arrived;
    private boolean failed;
    private String lastConfiguration = "";
    private double coverage;
    private long coverageMillis = -1;
    private int reportedTenths;

    private ReconnaissanceScenario(ScenarioFiles files, ReconnaissanceSettings settings, Consumer<Timeline.Row> printer) {
        this.settings = settings;
        this.arena = files.arena();
        this.log = new ScenarioLog(printer);
        if (arena.hazards().isEmpty()) {
            throw new IllegalArgumentException("arena '" + arena.name() + "' has no hazard; the reconnaissance needs some");
        }
        this.arrivals = arrivals();
        this.failing = "d2";
        var builder = TeamSimulation.builder(files.mission(), files.repository(), settings.seed())
                .vehicles(List.of(new SimVehicle("cdr", Set.of("communication"), Set.of(), true, false)))
                .security(settings.security()).auth(AuthMode.DENY).invariantChecks(false)
                .link(LinkProfile.DEFAULT.withLatency(5, 10).withLoss(settings.loss()))
                .world(arena).radio(HOUSE_RADIO).robotSpec(HOUSE_ROBOT).place("cdr", "cdr")
                .listener(this::cellEvent).output(this::policyOutput);
        for (Arrival a : arrivals) {
            builder.placeArriving(a.vehicle().id(), a.start());
        }
        this.team = builder.build();
        this.world = team.world();
        this.floor = new FloorCoverage(arena, grid(arena));
        SimWorld w = world.world();
        scene.roles(RoleLabels.of(labels)).trajectories(tracks).caption("the team enters the house");
        w.addListener(tracks);
        w.addListener(new WorldStepListener() {
            @Override
            public void stepped(SimWorld sw) {
                if (sw.steps() % FIX_EVERY_STEPS == 0) {
                    sw.robots().forEach(SimRobot::positionFix);
                }
                watch();
            }

            @Override
            public void disabled(SimWorld sw, SimRobot robot, String cause) {
                log.row(team.nowMillis(), robot.id(), "STOPPED", "disabled by " + cause + " at " + point(robot.x(), robot.y()));
            }
        });
        film = settings.film() == null ? null : new GifRecorder(new WorldPainter(), scene, settings.film());
        if (film != null) {
            w.addListener(film);
        }
    }

    /** The robots and when they enter: the minimal team first, then the rest of Fig. 2, then a spare. */
    private static List<Arrival> arrivals() {
        return List.of(
                new Arrival(SimVehicle.surveyor("s1"), "r10", 1_000),
                new Arrival(SimVehicle.surveyor("s2"), "r11", 4_000),
                new Arrival(SimVehicle.aggregator("a1"), "r1", 7_000),
                new Arrival(SimVehicle.detector("d1"), "r9", 12_000),
                new Arrival(SimVehicle.relay("r1"), "r12", 15_000),
                new Arrival(SimVehicle.detector("d2"), "r6", 18_000),
                new Arrival(SimVehicle.relay("r2"), "r7", 21_000),
                new Arrival(SimVehicle.surveyor("s3"), "r5", 100_000));
    }

    /**
     * The reconnaissance from a project folder: {@code missions/reconnaissance-house.instance.xml},
     * {@code missions/worlds/house.xml} and the policy repository {@code policies/}.
     *
     * @param printer receives each timeline row as it happens
     * @throws IOException      when a file is missing or cannot be read
     * @throws MissionException when the mission is invalid (every error listed)
     * @throws ArenaException   when the world file is invalid
     */
    public static ReconnaissanceScenario load(Path projectDir, ReconnaissanceSettings settings, Consumer<Timeline.Row> printer)
            throws IOException, MissionException, ArenaException {
        return new ReconnaissanceScenario(ScenarioFiles.load(projectDir, "reconnaissance-house.instance.xml", "house.xml"),
                settings, printer);
    }

    /** Runs until the goal is met or the time limit. */
    public ReconnaissanceOutcome run() {
        start();
        advance(settings.limitMillis());
        return finish();
    }

    /** Starts the commander's cell; the robots follow at their times. */
    public void start() {
        team.start();
        log.row(0, "cdr", "STARTED", "the commander's laptop waits at the house; " + arrivals.size() + " robots will enter");
    }

    /** Runs for at most {@code millis} of mission time, less if the run ends. */
    public void advance(long millis) {
        long end = Math.min(settings.limitMillis(), team.nowMillis() + Math.min(millis, settings.limitMillis()));
        while (!finished() && team.nowMillis() < end) {
            long next = end;
            if (arrived < arrivals.size()) {
                next = Math.min(next, arrivals.get(arrived).atMillis());
            }
            if (!failed && settings.failureMillis() >= 0) {
                next = Math.min(next, settings.failureMillis());
            }
            if (next > team.nowMillis()) {
                team.runUntil(this::finished, next - team.nowMillis());
            }
            events();
        }
    }

    /** Joins the robots whose time has come, and drains the failing robot's battery at its time. */
    private void events() {
        long now = team.nowMillis();
        while (arrived < arrivals.size() && arrivals.get(arrived).atMillis() <= now) {
            Arrival a = arrivals.get(arrived++);
            team.join(a.vehicle());
            log.row(now, a.vehicle().id(), "ENTERED", "switched on at the entrance (" + String.join(", ",
                    new java.util.TreeSet<>(a.vehicle().tasks())) + ")");
        }
        if (!failed && settings.failureMillis() >= 0 && now >= settings.failureMillis()) {
            failed = true;
            world.robot(failing).ifPresent(r -> {
                r.disable("battery");
                log.row(now, failing, "STOPPED", "battery flat at " + point(r.x(), r.y()) + ": drive and radio lost");
                scene.mark(new Mark.Cross(r.x(), r.y(), failing + ": battery"));
            });
            scene.caption(failing + "'s battery died: the team contracts");
        }
    }

    /** Whether the run is over: goal met or the time limit. */
    public boolean finished() {
        return goalMet() || team.nowMillis() >= settings.limitMillis();
    }

    private boolean goalMet() {
        return coverageMillis >= 0 && found.size() == arena.hazards().size();
    }

    /** Ends the run and tells how it went. */
    public ReconnaissanceOutcome finish() {
        watch();
        if (film != null) {
            film.capture(world.world());
        }
        long now = team.nowMillis();
        String summary = String.format(Locale.ROOT, "%.1f%% of the free floor mapped, hazards found %d of %d %s",
                coverage * 100, found.size(), arena.hazards().size(), found);
        if (goalMet()) {
            scene.caption("the hazard map is complete: " + summary);
            log.row(now, "-", "DONE", summary);
            return outcome(true, summary + " at " + seconds(now) + " s");
        }
        String why = "goal not met within " + seconds(settings.limitMillis()) + " s of mission time: " + summary;
        log.row(now, "-", "FAILED", why);
        return outcome(false, why);
    }

    private ReconnaissanceOutcome outcome(boolean ok, String reason) {
        return new ReconnaissanceOutcome(ok, reason, team.nowMillis(), coverage, coverageMillis, List.copyOf(found), List.copyOf(standings));
    }

    /**
     * The hazard map as a picture's scene: the aggregator's map over the house (floor it does not
     * know shaded), each hazard it holds as a diamond labelled with its kind and reports, the
     * robots' trajectories and where the failing robot stopped.
     */
    public Scene hazardMapScene() {
        Scene map = new Scene("Hazard map of the house (the aggregator's map and hazards)")
                .roles(RoleLabels.of(labels)).trajectories(tracks)
                .caption(String.format(Locale.ROOT, "%.0f%% of the free floor mapped, %d of %d hazards found", coverage * 100,
                        found.size(), arena.hazards().size()));
        aggregator().ifPresent(a -> {
            map.map(a.map());
            for (List<Object> h : a.hazards()) {
                map.mark(new Mark.Found(((Number) h.get(1)).doubleValue(), ((Number) h.get(2)).doubleValue(),
                        h.get(0) + " x" + h.get(3)));
            }
        });
        scene.marks().stream().filter(m -> m instanceof Mark.Cross).forEach(map::mark);
        return map;
    }

    /** The aggregator's map now, if an aggregator task is running. */
    public Optional<OccupancyGrid> hazardMap() {
        return aggregator().map(Aggregator::map);
    }

    private Optional<Aggregator> aggregator() {
        for (Arrival a : arrivals) {
            Cell c = cell(a.vehicle().id());
            if (c != null && c.seats().stream().anyMatch(s -> s.role().equals("aggregator"))) {
                return world.task(a.vehicle().id(), Aggregator.class);
            }
        }
        return Optional.empty();
    }

    private void watch() {
        for (Arrival a : arrivals) {
            Cell c = cell(a.vehicle().id());
            if (c != null) {
                List<String> held = new ArrayList<>();
                c.seats().forEach(s -> {
                    if (!held.contains(s.role())) {
                        held.add(s.role());
                    }
                });
                labels.put(a.vehicle().id(), held.isEmpty() ? "free" : String.join("+", held));
            }
        }
        Configurations.Snapshot config = Configurations.of(team);
        String text = config.describe();
        if (!text.equals(lastConfiguration)) {
            lastConfiguration = text;
            if (standings.isEmpty() || !standings.get(standings.size() - 1).equals(config.standing())) {
                standings.add(config.standing());
                scene.caption(config.standing() + " configuration");
            }
            log.row(team.nowMillis(), "team", "CONFIGURATION", text);
        }
        Optional<Aggregator> agg = aggregator();
        if (agg.isEmpty()) {
            return;
        }
        if (scene.map() != agg.get().map()) {
            scene.map(agg.get().map());
        }
        if (world.world().steps() % WATCH_EVERY_STEPS != 0 && !goalMet()) {
            return;
        }
        coverage = floor.of(agg.get().map());
        int tenths = (int) Math.floor(coverage * 10);
        if (tenths > reportedTenths) {
            reportedTenths = tenths;
            log.row(team.nowMillis(), "team", "MAPPED", String.format(Locale.ROOT, "%.0f%% of the free floor on the hazard map",
                    coverage * 100));
        }
        if (coverageMillis < 0 && coverage >= settings.coverageGoal()) {
            coverageMillis = team.nowMillis();
        }
        for (Arena.Hazard h : arena.hazards()) {
            if (found.contains(h.id())) {
                continue;
            }
            for (List<Object> reported : agg.get().hazards()) {
                if (reported.get(0).equals(h.kind()) && Math.hypot(((Number) reported.get(1)).doubleValue() - h.x(),
                        ((Number) reported.get(2)).doubleValue() - h.y()) <= FOUND_WITHIN) {
                    found.add(h.id());
                    log.row(team.nowMillis(), "team", "HAZARD_FOUND", h.id() + " (" + h.kind() + ") at " + point(h.x(), h.y())
                            + " is on the hazard map");
                    break;
                }
            }
        }
    }

    private void policyOutput(String vehicle, String line) {
        log.row(team.nowMillis(), vehicle, "POLICY", line);
    }

    private void cellEvent(CellEvent e) {
        switch (e.kind()) {
            case DISCOVERING, ASSIGNING, HOSTING, PUBLISHED, DELIVERED -> {
                return;   // protocol detail (maps go out every few seconds): not on the timeline
            }
            default -> log.row(e.timeMillis(), e.vehicle(), e.kind().name(), e.detail());
        }
    }

    /** What each live cell's policies reported as errors, by vehicle. */
    public Map<String, List<String>> diagnostics() {
        return ScenarioLog.diagnostics(team);
    }

    public Timeline timeline() {
        return log.timeline();
    }

    public ReconnaissanceSettings settings() {
        return settings;
    }

    public Scene scene() {
        return scene;
    }

    public SimWorld world() {
        return world.world();
    }

    public TeamSimulation team() {
        return team;
    }

    public TrajectoryRecorder trajectories() {
        return tracks;
    }

    /** The robots and their entrance times. */
    public List<Arrival> schedule() {
        return arrivals;
    }

    /** The robot whose battery dies. */
    public String failingRobot() {
        return failing;
    }

    public FloorCoverage floor() {
        return floor;
    }

    /** The film, if the settings asked for one. */
    public Optional<GifRecorder> film() {
        return Optional.ofNullable(film);
    }

    /** The live cell of a vehicle, or null (not entered yet, or crashed). */
    private Cell cell(String vehicle) {
        return team.isLive(vehicle) ? team.cell(vehicle) : null;
    }

    private static OccupancyGrid grid(Arena arena) {
        return new OccupancyGrid(0, 0, arena.width(), arena.height(), WorldTeam.MAP_RESOLUTION);
    }

    private static String seconds(long millis) {
        return String.format(Locale.ROOT, "%.1f", millis / 1000.0);
    }

    private static String point(double x, double y) {
        return String.format(Locale.ROOT, "(%.2f, %.2f)", x, y);
    }
}
