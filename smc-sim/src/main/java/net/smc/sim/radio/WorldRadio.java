package net.smc.sim.radio;

import java.util.Collections;
import java.util.HashMap;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.random.RandomGenerator;
import java.util.random.RandomGeneratorFactory;

import net.smc.core.transport.Address;
import net.smc.core.transport.sim.RadioModel;
import net.smc.sim.hardware.Radio;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.world.Arena;
import net.smc.sim.world.SimWorld;

/**
 * The radio between the world's robots and fixed stations, from their positions: range, walls in
 * the way and loss rising with distance ({@link RadioSettings}). As a {@link RadioModel} it lets
 * the in-memory network carry a datagram between two bound addresses with the link's quality as
 * probability, drawn from a generator seeded by the world's seed (the network asks in a
 * deterministic order, so runs replay). A disabled robot's radio is silent both ways. Links appear
 * and break as robots move: qualities are computed afresh for each step, and cached within it.
 *
 * <pre>{@code
 * network.setRadio(world.radio());
 * world.radio().bind(Address.loopback(4001), "s1");   // the cell at 4001 rides robot s1
 * }</pre>
 */
public final class WorldRadio implements RadioModel {
    private final SimWorld world;
    private final RadioSettings settings;
    private final RandomGenerator random;
    private final Map<Address, String> nodes = new HashMap<>();
    private final Map<String, Address> addresses = new HashMap<>();
    private final Map<Long, Double> cache = new HashMap<>();
    private final Map<String, Integer> numbers = new HashMap<>();
    private long cachedStep = -1;

    /** Made by the world; {@code seed} seeds the loss draws. */
    public WorldRadio(SimWorld world, RadioSettings settings, long seed) {
        this.world = Objects.requireNonNull(world, "world");
        this.settings = Objects.requireNonNull(settings, "settings");
        this.random = RandomGeneratorFactory.of("L64X128MixRandom").create(seed ^ 0x7AD10L);
    }

    /**
     * Binds the network address of a cell to the robot or station {@code nodeId} that carries it.
     *
     * @throws IllegalArgumentException when the address or the node is bound already
     */
    public void bind(Address address, String nodeId) {
        Objects.requireNonNull(address, "address");
        Objects.requireNonNull(nodeId, "nodeId");
        if (nodes.containsKey(address)) {
            throw new IllegalArgumentException("address " + address + " is bound to '" + nodes.get(address) + "' already");
        }
        if (addresses.containsKey(nodeId)) {
            throw new IllegalArgumentException("node '" + nodeId + "' is bound to " + addresses.get(nodeId) + " already");
        }
        nodes.put(address, nodeId);
        addresses.put(nodeId, address);
    }

    /** The robot or station bound to {@code address}, or null. */
    public String node(Address address) {
        return nodes.get(address);
    }

    /** The address bound to robot or station {@code nodeId}, or null. */
    public Address address(String nodeId) {
        return addresses.get(nodeId);
    }

    public RadioSettings settings() {
        return settings;
    }

    @Override
    public boolean reachable(Address from, Address to) {
        String a = nodes.get(from);
        String b = nodes.get(to);
        if (a == null || b == null) {
            return settings.unboundReaches() && (a == null || on(a)) && (b == null || on(b));
        }
        double quality = quality(a, b);
        return quality > 0 && random.nextDouble() < quality;
    }

    /** The quality of the link between two robots or stations now, 0 (none) to 1. */
    public double quality(String a, String b) {
        if (a.equals(b)) {
            return 0;
        }
        if (cachedStep != world.steps()) {
            cache.clear();
            cachedStep = world.steps();
        }
        int na = number(a);
        int nb = number(b);
        long key = na < nb ? ((long) na << 32) | nb : ((long) nb << 32) | na;
        Double known = cache.get(key);
        if (known == null) {
            known = compute(a, b);
            cache.put(key, known);
        }
        return known;
    }

    /** The {@link Radio} view of robot {@code id}: every other robot and station it has a link to. */
    public Radio view(String id) {
        return () -> neighbours(id);
    }

    private Map<String, Double> neighbours(String id) {
        Map<String, Double> out = new TreeMap<>();
        if (!on(id)) {
            return out;
        }
        for (SimRobot robot : world.robots()) {
            link(out, id, robot.id());
        }
        for (Arena.Station station : world.arena().stations()) {
            link(out, id, station.id());
        }
        return Collections.unmodifiableMap(out);
    }

    private void link(Map<String, Double> out, String self, String other) {
        double q = quality(self, other);
        if (q > 0) {
            out.put(other, q);
        }
    }

    private double compute(String a, String b) {
        double[] pa = position(a);
        double[] pb = position(b);
        if (pa == null || pb == null || !on(a) || !on(b)) {
            return 0;
        }
        double d = Math.hypot(pb[0] - pa[0], pb[1] - pa[1]);
        if (d > settings.range()) {
            return 0;
        }
        double r = d / settings.range();
        double q = 1 - r * r * r * r;
        if (settings.wallFactor() < 1) {
            q *= Math.pow(settings.wallFactor(), world.wallsBetween(pa[0], pa[1], pb[0], pb[1]));
        }
        return q < settings.minQuality() ? 0 : q;
    }

    private boolean on(String id) {
        SimRobot robot = world.robot(id);
        return robot == null || robot.radioOn();
    }

    private double[] position(String id) {
        SimRobot robot = world.robot(id);
        if (robot != null) {
            return new double[] {robot.x(), robot.y()};
        }
        for (Arena.Station station : world.arena().stations()) {
            if (station.id().equals(id)) {
                return new double[] {station.x(), station.y()};
            }
        }
        return null;
    }

    private int number(String id) {
        return numbers.computeIfAbsent(id, k -> numbers.size());
    }
}
