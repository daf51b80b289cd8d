package net.smc.sim.team;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.cell.Cell;
import net.smc.core.role.TaskProvider;
import net.smc.core.task.Task;
import net.smc.core.task.TaskDescriptionException;
import net.smc.core.transport.Address;
import net.smc.policy.RunResult;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.task.ClearWay;
import net.smc.sim.task.TaskCatalog;
import net.smc.sim.task.TaskContext;
import net.smc.sim.arena.Arena;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.WorldStepListener;

/**
 * The world's side of a {@link TeamSimulation}: which robot or station carries each vehicle, the
 * vehicles' tasks on that hardware, and what the hardware tells the cells. A robot's cell reports
 * its odometry position as its state (so a parent that loses it hands that position over to its
 * replacement, Table II); a station's control loops run once per world step.
 */
public final class WorldTeam {
    /** Map resolution of each vehicle's own occupancy grid, metres: coarse enough that a task state
     *  with the map (the Aggregator's) fits the wire's list limit of 64 elements on a 12 x 8 m arena. */
    public static final double MAP_RESOLUTION = 0.25;
    /** World steps between two position reports of a robot. */
    private static final int REPORT_EVERY = 5;

    private final CellTeam team;
    private final SimWorld world;
    private final TaskCatalog catalog;
    private final Map<String, String> places;
    private final Map<String, List<String>> standalone;
    private final Map<String, RobotHardware> hardware = new LinkedHashMap<>();
    private final Map<String, StationHardware> stations = new LinkedHashMap<>();
    private final Map<String, Map<String, Task>> tasks = new LinkedHashMap<>();
    private final Map<String, RadioSignal> signals = new LinkedHashMap<>();
    /** Each robot's {@link ClearWay}, with its latest boot's tasks. */
    private final Map<String, ClearWay> clearWays = new LinkedHashMap<>();

    WorldTeam(CellTeam team, SimWorld world, TaskCatalog catalog, Map<String, String> places,
              Map<String, List<String>> standalone) {
        this.team = team;
        this.world = world;
        this.catalog = catalog;
        this.places = Map.copyOf(places);
        this.standalone = Map.copyOf(standalone);
        Arena arena = world.arena();
        for (Map.Entry<String, String> p : places.entrySet()) {
            String vehicle = p.getKey();
            String where = p.getValue();
            if (arena.start(where).isPresent()) {
                hardware.put(vehicle, world.addRobot(vehicle, where));
            } else {
                Arena.Station station = arena.stations().stream().filter(s -> s.id().equals(where)).findFirst()
                        .orElseThrow(() -> new IllegalArgumentException("vehicle '" + vehicle + "' is placed at '" + where
                                + "', which is neither a start nor a station of arena '" + arena.name() + "' (starts: "
                                + arena.starts().stream().map(Arena.Start::id).toList() + ", stations: "
                                + arena.stations().stream().map(Arena.Station::id).toList() + ")"));
                StationHardware s = new StationHardware(vehicle, station, world);
                hardware.put(vehicle, s);
                stations.put(vehicle, s);
            }
        }
        for (String vehicle : standalone.keySet()) {
            if (!places.containsKey(vehicle)) {
                throw new IllegalArgumentException("standalone vehicle '" + vehicle + "' is not placed in the world");
            }
        }
        world.addListener(new WorldStepListener() {
            @Override
            public void stepped(SimWorld w) {
                step();
            }
        });
    }

    void checkPlaces(Set<String> vehicles, Set<String> arriving) {
        List<String> unplaced = vehicles.stream().filter(v -> !places.containsKey(v)).toList();
        if (!unplaced.isEmpty()) {
            throw new IllegalArgumentException("vehicles " + unplaced + " are not placed in the world; place every vehicle");
        }
        List<String> unknown = places.keySet().stream().filter(v -> !vehicles.contains(v) && !arriving.contains(v)).toList();
        if (!unknown.isEmpty()) {
            throw new IllegalArgumentException("placed vehicles " + unknown + " are not in the simulation");
        }
    }

    void start() {
        world.start();
    }

    boolean placed(String vehicle) {
        return places.containsKey(vehicle);
    }

    /** Binds a vehicle's address to the robot or station that carries it. */
    void bind(String vehicle, Address address) {
        String where = places.get(vehicle);
        if (where == null) {
            throw new IllegalArgumentException("vehicle '" + vehicle + "' is not placed in the world; place every vehicle");
        }
        world.radio().bind(address, stations.containsKey(vehicle) ? where : vehicle);
    }

    /** The vehicle's tasks: made afresh from the catalog each time its cell boots. */
    TaskProvider tasks(String vehicle) {
        SimVehicle spec = team.vehicle(vehicle);
        Arena arena = world.arena();
        OccupancyGrid map = new OccupancyGrid(0, 0, arena.width(), arena.height(), MAP_RESOLUTION);
        TaskContext context = new TaskContext(hardware.get(vehicle), map);
        Map<String, Task> own = new TreeMap<>();
        for (String name : spec.tasks()) {
            own.put(name, catalog.create(name, context));
        }
        tasks.put(vehicle, own);
        // A robot that no task drives leaves a narrow passage; one behaviour a robot, with this boot's tasks.
        ClearWay before = clearWays.remove(vehicle);
        if (before != null) {
            context.hardware().control(before, null);
        }
        if (context.hardware().has(RobotHardware.Device.DRIVE)) {
            clearWays.put(vehicle, ClearWay.install(context, List.copyOf(own.values()), before));
        }
        return TaskProvider.of(own);
    }

    /** The capability description of a placed vehicle: its resources and its tasks' Table V descriptions. */
    CapabilityDescription describe(SimVehicle spec) {
        List<String> unknown = spec.tasks().stream().filter(t -> !catalog.contains(t)).sorted().toList();
        if (!unknown.isEmpty()) {
            throw new IllegalArgumentException("vehicle '" + spec.id() + "' has tasks " + unknown
                    + " that the task catalog does not know (it knows " + catalog.names() + ")");
        }
        return CapabilityDescription.of(spec.id(), new java.util.TreeSet<>(spec.resources()),
                spec.tasks().stream().sorted().map(catalog::describe).toList());
    }

    /** Before the cell starts: gives it the radio's signal object. */
    void install(String vehicle, Cell cell) {
        signals.computeIfAbsent(vehicle, v -> new RadioSignal(team, v)).install(cell.engine());
    }

    /** After the cell started: a standalone vehicle's tasks start and its files load. */
    void booted(String vehicle, Cell cell, TaskProvider provider) {
        List<String> uris = standalone.get(vehicle);
        if (uris == null) {
            return;
        }
        for (String name : provider.names()) {
            Task task = provider.task(name).orElseThrow();
            try {
                task.bind(cell.engine());
            } catch (TaskDescriptionException e) {
                throw new IllegalStateException("vehicle '" + vehicle + "': task " + name + " cannot be bound: " + e.getMessage(), e);
            }
            task.start();
        }
        for (String uri : uris) {
            RunResult r = cell.engine().load(uri);
            if (r.status() != RunResult.Status.OK) {
                throw new IllegalStateException("vehicle '" + vehicle + "': " + uri + " failed: " + r.diagnostics());
            }
        }
    }

    private long steps;

    private void step() {
        double time = world.time();
        double dt = world.stepMillis() / 1000.0;
        for (StationHardware s : stations.values()) {
            s.step(time, dt);
        }
        if (steps++ % REPORT_EVERY != 0) {
            return;
        }
        for (Map.Entry<String, RobotHardware> e : hardware.entrySet()) {
            if (e.getValue() instanceof SimRobot robot && team.isLive(e.getKey())) {
                var pose = robot.odometry().pose();
                List<Object> state = new ArrayList<>(List.of(decimal(pose.x()), decimal(pose.y())));
                team.cell(e.getKey()).reportState(state);
            }
        }
    }

    /** Millimetres are enough, and a state's numbers are PonderTalk numbers (decimals). */
    private static java.math.BigDecimal decimal(double v) {
        return java.math.BigDecimal.valueOf(Math.round(v * 1000), 3);
    }

    /** The vehicles whose robot's radio is off (a disabled robot): they hear no one and no one hears them. */
    Set<String> silent() {
        Set<String> out = new java.util.HashSet<>();
        hardware.forEach((v, h) -> {
            if (h instanceof SimRobot r && !r.radioOn()) {
                out.add(v);
            }
        });
        return out;
    }

    public SimWorld world() {
        return world;
    }

    /** The robot of a vehicle, if it has one. */
    public Optional<SimRobot> robot(String vehicle) {
        return hardware.get(vehicle) instanceof SimRobot r ? Optional.of(r) : Optional.empty();
    }

    /** The task instance of that name the vehicle's cell got when it last booted. */
    public <T extends Task> Optional<T> task(String vehicle, Class<T> type) {
        Map<String, Task> own = tasks.getOrDefault(vehicle, Map.of());
        for (Task t : own.values()) {   // a loop, not a stream: scenarios ask this after every step
            if (type.isInstance(t)) {
                return Optional.of(type.cast(t));
            }
        }
        return Optional.empty();
    }
}
