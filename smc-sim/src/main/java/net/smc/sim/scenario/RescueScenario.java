package net.smc.sim.scenario;

import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;

import net.smc.core.cell.Cell;
import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Seat;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionException;
import net.smc.core.transport.sim.LinkProfile;
import net.smc.policy.api.AuthMode;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.render.GifRecorder;
import net.smc.sim.render.Mark;
import net.smc.sim.render.RoleLabels;
import net.smc.sim.render.Scene;
import net.smc.sim.render.Timeline;
import net.smc.sim.render.TrajectoryRecorder;
import net.smc.sim.render.WorldPainter;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.task.Assist;
import net.smc.sim.team.CellTeam;
import net.smc.sim.team.LiveTeam;
import net.smc.sim.team.SimVehicle;
import net.smc.sim.team.TeamSimulation;
import net.smc.sim.team.TeamSimulationBuilder;
import net.smc.sim.team.WorldTeam;
import net.smc.sim.arena.Arena;
import net.smc.sim.arena.ArenaException;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.WorldStepListener;

/**
 * The rescue of a wounded soldier (the paper's section IV-C, Fig. 7) run by cells and policies:
 * the commander's laptop ({@code cdr}) and the soldier's wearable computer ({@code wearable}) at
 * their stations, two robots ({@code r1}, {@code r2}) at their starts, on the world's radio,
 * with authenticated traffic and policies checked against a default of deny, as deployed. The scenario only wounds the soldier (step (i)); the wearable's
 * policy calls for help (ii); the commander's policy, which has held its recruiting since the
 * role was loaded, resumes it on the distress, and Table I assembles the team (iii); the surveyor's policy drives it
 * to the soldier until the hazard stops it (iv), Table II re-assigns its role on the failure
 * timeout with its last position (v), the new surveyor's policy avoids that zone (vi) and
 * delivers assistance (vii).
 *
 * <pre>{@code
 * RescueScenario rescue = RescueScenario.load(Path.of("."), RescueScenario.Settings.of(7));
 * RescueScenario.Outcome outcome = rescue.run();   // outcome.succeeded(), rescue.timeline() ...
 * }</pre>
 *
 * <p>{@link #loadLive} runs the same scenario with every cell on real UDP over loopback and the
 * world stepped in real time ({@link LiveTeam}); close it when done.
 */
public final class RescueScenario implements AutoCloseable {
    /** The robots' resources and tasks: able to navigate, communicate, survey and detect hazards. */
    static final Set<String> ROBOT_RESOURCES = Set.of("motion", "video", "chemical", "communication");
    static final Set<String> ROBOT_TASKS = Set.of("Navigator", "Assist", "HazardDetector", "Aggregator");
    /** The wearable's files, loaded when its cell boots. */
    static final List<String> WEARABLE_POLICIES = List.of("policy:/soldier/wearable");
    /** The two robots, in the order the scenario looks at them. */
    private static final List<String> ROBOTS = List.of("r1", "r2");

    /**
     * How to run it.
     *
     * @param seed         fixes every random draw of the run
     * @param loss         probability that the network loses a datagram, on top of the radio, 0 to below 1
     * @param limitMillis  mission time after which the run gives up, ms
     * @param security     how cells authenticate
     * @param film         settings of the GIF film, or null for none
     */
    public record Settings(long seed, double loss, long limitMillis, TeamSimulation.Security security,
                           GifRecorder.Settings film) {
        public Settings {
            if (!(loss >= 0 && loss < 1)) {
                throw new IllegalArgumentException("loss " + loss + " is out of range; it must be 0 or more and below 1");
            }
            if (limitMillis <= 0) {
                throw new IllegalArgumentException("limit " + limitMillis + " ms must be positive");
            }
            Objects.requireNonNull(security, "security");
        }

        /** No extra loss, 180 s of mission time, real signatures, no film. */
        public static Settings of(long seed) {
            return new Settings(seed, 0, 180_000, TeamSimulation.Security.REAL, null);
        }

        public Settings withLoss(double p) {
            return new Settings(seed, p, limitMillis, security, film);
        }

        public Settings withLimit(long millis) {
            return new Settings(seed, loss, millis, security, film);
        }

        public Settings withFilm(GifRecorder.Settings f) {
            return new Settings(seed, loss, limitMillis, security, f);
        }

        public Settings withSecurity(TeamSimulation.Security s) {
            return new Settings(seed, loss, limitMillis, s, film);
        }
    }

    /**
     * How a run ended.
     *
     * @param succeeded        whether assistance was delivered to the soldier
     * @param reason           why not, or what succeeded
     * @param missionMillis    mission time at the end, ms
     * @param firstStopMillis  when the first surveyor was stopped by the hazard, or -1
     * @param reassignedMillis when the surveyor role was re-assigned after that, or -1
     * @param firstSurveyor    the vehicle that was surveyor first, or null
     * @param secondSurveyor   the vehicle that took over the role, or null
     * @param closestToHazard  the second surveyor's closest approach to the hazard's centre, m (NaN if none)
     */
    public record Outcome(boolean succeeded, String reason, long missionMillis, long firstStopMillis,
                          long reassignedMillis, String firstSurveyor, String secondSurveyor, double closestToHazard) {
    }

    private final Settings settings;
    private final CellTeam team;
    private final WorldTeam world;
    private final Arena.Hazard hazard;
    private final TrajectoryRecorder tracks = new TrajectoryRecorder(5);
    private final Scene scene = new Scene("Rescue of a wounded soldier (cf. the paper's Fig. 7)");
    private final Map<String, String> roles = new LinkedHashMap<>();
    private final GifRecorder film;
    private final ScenarioLog log;
    private long firstStop = -1;
    private long reassigned = -1;
    private String firstSurveyor;
    private String secondSurveyor;
    private double closest = Double.NaN;
    private String trouble;
    private boolean zoneMarked;
    private long distressHeard = -1;

    /** Makes the team of the scenario from its settings: a simulation, or a live team. */
    @FunctionalInterface
    interface TeamMaker {
        CellTeam make(TeamSimulationBuilder builder) throws IOException;
    }

    private RescueScenario(Mission mission, PolicyRepository repository, Arena arena, Settings settings,
                           Consumer<Timeline.Row> printer, TeamMaker maker) throws IOException {
        this.settings = settings;
        this.log = new ScenarioLog(printer);
        this.hazard = arena.hazards().stream().findFirst()
                .orElseThrow(() -> new IllegalArgumentException("arena '" + arena.name() + "' has no hazard; the rescue needs one"));
        List<SimVehicle> vehicles = List.of(
                new SimVehicle("cdr", Set.of("communication"), Set.of(), true, false),
                new SimVehicle("wearable", Set.of("bodySensors"), Set.of("Beacon"), false, false),
                new SimVehicle("r1", ROBOT_RESOURCES, ROBOT_TASKS, false, false),
                new SimVehicle("r2", ROBOT_RESOURCES, ROBOT_TASKS, false, false));
        this.team = maker.make(TeamSimulation.builder(mission, repository, settings.seed())
                .vehicles(vehicles).security(settings.security()).auth(AuthMode.DENY)
                .link(LinkProfile.DEFAULT.withLatency(5, 10).withLoss(settings.loss()))
                .world(arena).place("cdr", "cdr").place("wearable", "wearable").place("r1", "r1").place("r2", "r2")
                .standalone("wearable", WEARABLE_POLICIES)
                .listener(this::cellEvent).output(this::policyOutput));
        this.world = team.world();
        SimWorld w = world.world();
        scene.roles(RoleLabels.of(roles)).trajectories(tracks).caption("(i) the soldier is wounded");
        w.addListener(tracks);
        w.addListener(new WorldStepListener() {
            @Override
            public void stepped(SimWorld sw) {
                watch();
            }

            @Override
            public void disabled(SimWorld sw, SimRobot robot, String cause) {
                stopped(robot, cause);
            }
        });
        if (settings.film() != null) {
            film = new GifRecorder(new WorldPainter(), scene, settings.film());
            w.addListener(film);
        } else {
            film = null;
        }
    }

    /**
     * The rescue from a project folder: {@code missions/rescue.instance.xml},
     * {@code missions/worlds/rescue.xml} and the policy repository {@code policies/}.
     *
     * @param printer receives each timeline row as it happens
     * @throws IOException      when a file cannot be read
     * @throws MissionException when the mission is invalid (every error listed)
     * @throws ArenaException   when the world file is invalid
     */
    public static RescueScenario load(Path projectDir, Settings settings, Consumer<Timeline.Row> printer)
            throws IOException, MissionException, ArenaException {
        return load(projectDir, settings, printer, TeamSimulationBuilder::build);
    }

    /**
     * The rescue with every cell on its own UDP sockets over loopback and the world stepped in
     * real time, {@code speed} mission seconds per wall second ({@link LiveTeam}). The settings'
     * security is ignored (traffic is always signed with fresh keys); its loss drops arriving
     * datagrams. Close the scenario when done.
     */
    public static RescueScenario loadLive(Path projectDir, Settings settings, double speed, Consumer<Timeline.Row> printer)
            throws IOException, MissionException, ArenaException {
        return load(projectDir, settings, printer, b -> LiveTeam.open(b, speed));
    }

    private static RescueScenario load(Path projectDir, Settings settings, Consumer<Timeline.Row> printer, TeamMaker maker)
            throws IOException, MissionException, ArenaException {
        ScenarioFiles files = ScenarioFiles.load(projectDir, "rescue.instance.xml", "rescue.xml");
        return new RescueScenario(files.mission(), files.repository(), files.arena(), settings, printer, maker);
    }

    /** Runs the rescue until assistance is delivered, something goes wrong, or the time limit. */
    public Outcome run() {
        start();
        advance(settings.limitMillis());
        return finish();
    }

    /** Starts the cells and wounds the soldier (step (i)); then {@link #advance} and {@link #finish}. */
    public void start() {
        team.start();
        team.exclusive(() -> {
            row(team.nowMillis(), "wearable", "WOUNDED", "the soldier is wounded: critical", "i");
            team.cell("wearable").engine().raise("root/event/wounded", "wounded", "critical");
            scene.caption("(ii) the wearable computer calls for help");
            return null;
        });
    }

    /** Runs for at most {@code millis} of mission time, less if the run ends. */
    public void advance(long millis) {
        long left = settings.limitMillis() - team.nowMillis();
        if (!finished() && left > 0) {
            team.runUntil(this::finished, Math.min(millis, left));
        }
    }

    /** Whether the run is over: assistance delivered, trouble, or the time limit. */
    public boolean finished() {
        return assisted().isPresent() || trouble != null || team.nowMillis() >= settings.limitMillis();
    }

    /** Ends the run and tells how it went. */
    public Outcome finish() {
        return team.exclusive(this::conclude);
    }

    private Outcome conclude() {
        if (film != null) {
            film.capture(world.world());
        }
        long now = team.nowMillis();
        Optional<String> rescuer = assisted();
        if (rescuer.isPresent()) {
            scene.caption("(vii) " + rescuer.get() + " reached the soldier and delivered assistance");
            return outcome(true, rescuer.get() + " delivered assistance to the soldier at " + seconds(now) + " s");
        }
        String why = trouble != null ? trouble
                : "no assistance delivered within " + seconds(settings.limitMillis()) + " s of mission time";
        row(now, "-", "FAILED", why, "");
        return outcome(false, why);
    }

    private Outcome outcome(boolean ok, String reason) {
        return new Outcome(ok, reason, team.nowMillis(), firstStop, reassigned, firstSurveyor, secondSurveyor, closest);
    }

    private Optional<String> assisted() {
        for (String r : ROBOTS) {
            Optional<Assist> assist = world.task(r, Assist.class);
            if (assist.isPresent() && assist.get().hasAssisted()) {
                return Optional.of(r);
            }
        }
        return Optional.empty();
    }

    /** Who holds the surveyor role now. */
    private Optional<String> surveyor() {
        for (String r : ROBOTS) {
            Cell c = team.cell(r);
            if (c != null) {
                for (Seat s : c.seats()) {
                    if (s.role().equals("surveyor")) {
                        return Optional.of(r);
                    }
                }
            }
        }
        return Optional.empty();
    }

    private void watch() {
        for (String r : ROBOTS) {
            Cell c = team.cell(r);
            if (c != null) {
                List<Seat> seats = c.seats();
                roles.put(r, seats.isEmpty() ? null : seats.get(0).role());
            }
        }
        if (firstSurveyor != null && firstStop >= 0) {
            roles.put(firstSurveyor, "former surveyor");
        }
        if (firstSurveyor == null) {
            surveyor().ifPresent(s -> firstSurveyor = s);
        }
        if (secondSurveyor != null && !zoneMarked && team.cell(secondSurveyor) != null) {
            List<Object> state = team.cell(secondSurveyor).handedOver();
            if (state.size() >= 2 && state.get(0) instanceof Number x && state.get(1) instanceof Number y) {
                scene.mark(new Mark.AvoidedZone(x.doubleValue(), y.doubleValue(), 1.7, "zone avoided by " + secondSurveyor));
                zoneMarked = true;
            }
        }
        if (secondSurveyor != null) {
            SimRobot robot = world.robot(secondSurveyor).orElseThrow();
            double d = Math.hypot(robot.x() - hazard.x(), robot.y() - hazard.y());
            closest = Double.isNaN(closest) ? d : Math.min(closest, d);
        }
    }

    private void stopped(SimRobot robot, String cause) {
        long now = team.nowMillis();
        if (firstStop < 0 && robot.id().equals(firstSurveyor)) {
            firstStop = now;
            row(now, robot.id(), "STOPPED", "disabled by " + cause + " at " + point(robot.x(), robot.y())
                    + ": drive and radio lost", "iv");
            scene.caption("(iv) surveyor " + robot.id() + " stopped by the hazard");
        } else {
            row(now, robot.id(), "STOPPED", "disabled by " + cause + " at " + point(robot.x(), robot.y()), "");
            trouble = robot.id() + " was disabled by " + cause + " too";
        }
    }

    private void cellEvent(CellEvent e) {
        String step = "";
        switch (e.kind()) {
            case ACCEPTED -> {
                boolean surveyor = e.detail().startsWith("surveyor");
                if (firstStop >= 0 && surveyor && !e.vehicle().equals(firstSurveyor)) {
                    step = "v";
                    if (reassigned < 0) {
                        reassigned = e.timeMillis();
                        secondSurveyor = e.vehicle();
                    }
                } else if (firstStop < 0 && distressHeard >= 0) {
                    step = "iii";
                }
            }
            case FAILURE, REASSIGNING -> step = firstStop >= 0 ? "v" : "";
            case ASSIGNED, MISSION_STATE, COMMANDING -> step = firstStop >= 0 ? "v" : distressHeard >= 0 ? "iii" : "";
            case DISCOVERING, ASSIGNING, HOSTING -> {
                return;   // protocol detail: not on the timeline
            }
            default -> { }
        }
        if (firstStop >= 0 && e.vehicle().equals(firstSurveyor)) {
            step = "";   // the stopped robot, cut off by its dead radio, acts on its own
        }
        row(e.timeMillis(), e.vehicle(), e.kind().name(), e.detail(), step);
        if (step.equals("v") && e.kind() == CellEvent.Kind.ACCEPTED && e.vehicle().equals(secondSurveyor)) {
            scene.caption("(v) " + secondSurveyor + " takes over the surveyor role");
        }
    }

    private void policyOutput(String vehicle, String line) {
        String step;
        if (line.startsWith("soldier wounded")) {
            step = "i";
        } else if (line.startsWith("distress from")) {
            step = "ii";
            if (vehicle.equals("cdr") && distressHeard < 0) {
                distressHeard = team.nowMillis();
            }
        } else if (line.startsWith("heading for the soldier")) {
            step = vehicle.equals(secondSurveyor) ? "vi" : "iv";
        } else if (line.startsWith("took over")) {
            step = "vi";
            scene.caption("(vi) " + vehicle + " goes round the zone");
        } else if (line.startsWith("Received event:UAVFailure")) {
            step = "v";
        } else if (line.startsWith("arrived") || line.startsWith("assistance")) {
            step = "vii";
        } else {
            step = "";
        }
        if (firstStop >= 0 && vehicle.equals(firstSurveyor)) {
            step = "";   // the stopped robot, cut off by its dead radio, acts on its own
        }
        row(team.nowMillis(), vehicle, "POLICY", line, step);
    }

    private void row(long millis, String vehicle, String what, String detail, String step) {
        log.row(millis, vehicle, what, detail, step);
    }

    /** What each live cell's policies reported as errors (a policy denied, a failed send ...), by vehicle. */
    public Map<String, List<String>> diagnostics() {
        return team.exclusive(() -> ScenarioLog.diagnostics(team));
    }

    public Timeline timeline() {
        return log.timeline();
    }

    /** When the commander heard the soldier's distress (step (ii)), ms of mission time, or -1. */
    public long distressHeardMillis() {
        return distressHeard;
    }

    public Scene scene() {
        return scene;
    }

    public SimWorld world() {
        return world.world();
    }

    /** The team: a {@link TeamSimulation}, or a {@link LiveTeam} when loaded with {@link #loadLive}. */
    public CellTeam team() {
        return team;
    }

    /** Stops the team's threads and closes its sockets, if it has any (a live team); the world stays to be drawn. */
    @Override
    public void close() {
        team.close();
    }

    public TrajectoryRecorder trajectories() {
        return tracks;
    }

    public Arena.Hazard hazard() {
        return hazard;
    }

    /** The film, if the settings asked for one. */
    public Optional<GifRecorder> film() {
        return Optional.ofNullable(film);
    }

    /** One timeline row as a line: {@code  12.345 s  r1        STOPPED   (iv) detail}. */
    public static String format(Timeline.Row r) {
        return ScenarioLog.format(r);
    }

    private static String seconds(long millis) {
        return String.format(Locale.ROOT, "%.1f", millis / 1000.0);
    }

    private static String point(double x, double y) {
        return String.format(Locale.ROOT, "(%.2f, %.2f)", x, y);
    }
}
