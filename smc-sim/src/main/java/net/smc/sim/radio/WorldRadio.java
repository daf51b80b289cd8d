package net.smc.sim.radio;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.random.RandomGenerator;
import java.util.random.RandomGeneratorFactory;

import net.smc.core.transport.Address;
import net.smc.core.transport.sim.RadioModel;
import net.smc.sim.hardware.Radio;

/**
 * The radio between the world's robots and fixed stations, from their positions: range, walls in
 * the way and loss rising with distance ({@link RadioSettings}). As a {@link RadioModel} it lets
 * the in-memory network carry a datagram between two bound addresses with the link's quality as
 * probability, drawn from a generator seeded by the world's seed (the network asks in a
 * deterministic order, so runs replay). A disabled robot's radio is silent both ways, from the
 * moment it is disabled.
 *
 * <p>Links appear and break as robots move, at the refresh rate of the settings
 * ({@link RadioSettings#refreshMillis()}, 100 ms by default): at the end of every world step whose
 * count is a multiple of the refresh period in steps, the radio takes every node's position, and
 * until the next refresh every link's quality is that of those positions. A pair's quality is
 * computed when first asked after a refresh that moved one of its ends, and kept otherwise, so
 * links between still robots cost nothing; with a refresh of one step the model is the
 * per-step one.
 *
 * <pre>{@code
 * network.setRadio(world.radio());
 * world.radio().bind(Address.loopback(4001), "s1");   // the cell at 4001 rides robot s1
 * }</pre>
 */
public final class WorldRadio implements RadioModel {
    private final RadioGround world;
    private final RadioSettings settings;
    private final RandomGenerator random;
    private final Map<Address, String> nodes = new HashMap<>();
    private final Map<String, Address> addresses = new HashMap<>();
    private final int refreshSteps;
    // Robots and stations are numbered as first seen. Their positions at the last refresh are in
    // x/y (placed: known); movedIn holds the refresh (generation) at which a node last moved. A
    // pair's quality is kept in a capacity x capacity table, valid while computedIn is no older
    // than the movedIn of either end.
    private final Map<String, Integer> numbers = new HashMap<>();
    private final List<String> ids = new ArrayList<>();
    private RadioGround.Node[] located = new RadioGround.Node[0];
    private double[] x = new double[0];
    private double[] y = new double[0];
    private boolean[] placed = new boolean[0];
    private boolean[] off = new boolean[0];   // radio off: read when first located, then told (switchedOff)
    private long[] movedIn = new long[0];
    private int capacity;
    private double[] cache = new double[0];
    private long[] computedIn = new long[0];
    private long generation;
    private int[] sorted;
    private int sortedNodes;

    /** Made by the world, which tells it of positions and walls; {@code seed} seeds the loss draws. */
    public WorldRadio(RadioGround ground, RadioSettings settings, long seed) {
        this.world = Objects.requireNonNull(ground, "ground");
        this.settings = Objects.requireNonNull(settings, "settings");
        this.random = RandomGeneratorFactory.of("L64X128MixRandom").create(seed ^ 0x7AD10L);
        this.refreshSteps = Math.max(1, (int) Math.round(settings.refreshMillis() / (double) ground.stepMillis()));
    }

    /**
     * Told by the world at the end of each step: on every {@code refreshSteps}-th step the radio
     * takes the nodes' positions afresh.
     */
    public void stepped() {
        if (world.steps() % refreshSteps == 0) {
            refresh();
        }
    }

    /** The refresh period in world steps. */
    public int refreshSteps() {
        return refreshSteps;
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
            return settings.unboundReaches() && (a == null || on(number(a))) && (b == null || on(number(b)));
        }
        double quality = quality(a, b);
        return quality > 0 && random.nextDouble() < quality;
    }

    /** The quality of the link between two robots or stations now, 0 (none) to 1. */
    public double quality(String a, String b) {
        if (a.equals(b)) {
            return 0;
        }
        return quality(number(a), number(b));
    }

    /** The {@link Radio} view of robot {@code id}: every other robot and station it has a link to. */
    public Radio view(String id) {
        return () -> neighbours(id);
    }

    private Map<String, Double> neighbours(String id) {
        int self = number(id);
        if (!on(self)) {
            return Collections.emptyMap();
        }
        int[] order = sortedNodes();
        String[] keys = new String[order.length];
        double[] values = new double[order.length];
        int n = 0;
        for (int other : order) {
            if (other != self) {
                double q = quality(self, other);
                if (q > 0) {
                    keys[n] = ids.get(other);
                    values[n++] = q;
                }
            }
        }
        return new Neighbours(keys, values, n);
    }

    /** The quality between two numbered nodes, computed once per refresh that moved one of them. */
    private double quality(int na, int nb) {
        if (generation == 0) {
            refresh();   // asked before the first step
        }
        if (!on(na) || !on(nb) || !placed(na) || !placed(nb)) {
            return 0;
        }
        int lo = Math.min(na, nb);
        int hi = Math.max(na, nb);
        int key = lo * capacity + hi;
        if (computedIn[key] < Math.max(movedIn[lo], movedIn[hi])) {
            cache[key] = compute(lo, hi);
            computedIn[key] = generation;
        }
        return cache[key];
    }

    /** Takes every node's position now; a node that moved invalidates its pairs. */
    private void refresh() {
        generation++;
        sortedNodes();   // numbers robots added since the last refresh
        for (int n = 0; n < ids.size(); n++) {
            RadioGround.Node at = node(n);
            if (at != null) {
                place(n, at);
            }
        }
    }

    private void place(int n, RadioGround.Node at) {
        double nx = at.x();
        double ny = at.y();
        if (!placed[n] || nx != x[n] || ny != y[n]) {
            x[n] = nx;
            y[n] = ny;
            placed[n] = true;
            movedIn[n] = generation;
        }
    }

    /** Whether the node has a position; one first seen between refreshes is placed where it is then. */
    private boolean placed(int n) {
        if (!placed[n]) {
            RadioGround.Node at = node(n);
            if (at == null) {
                return false;
            }
            place(n, at);
        }
        return true;
    }

    /** The open-air quality of the link between two placed nodes, walls counted; 0 below the minimum. */
    private double compute(int a, int b) {
        double ax = x[a];
        double ay = y[a];
        double bx = x[b];
        double by = y[b];
        double range = settings.range();
        double d2 = (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
        if (d2 > range * range * (1 + 1e-9)) {
            return 0;   // clearly out of range: spare the exact test
        }
        double d = Math.hypot(bx - ax, by - ay);
        if (d > range) {
            return 0;
        }
        double r = d / range;
        double q = 1 - r * r * r * r;
        if (settings.wallFactor() < 1) {
            q *= Math.pow(settings.wallFactor(), world.wallsBetween(ax, ay, bx, by, wallsAllowed(q)));
        }
        return q < settings.minQuality() ? 0 : q;
    }

    /** The most walls through which a link of open-air quality {@code q} stays at or above the minimum. */
    private int wallsAllowed(double q) {
        double f = settings.wallFactor();
        if (f == 0) {
            return 0;
        }
        // a margin of one wall against rounding: counting one further never changes the result
        double walls = Math.log(settings.minQuality() / q) / Math.log(f);
        return walls >= Integer.MAX_VALUE - 2 || Double.isNaN(walls) ? Integer.MAX_VALUE - 2 : Math.max(0, (int) walls + 1);
    }

    /** Every robot and station by id, robots added since the last call included. */
    private int[] sortedNodes() {
        int count = world.nodeCount();
        if (sorted == null || sortedNodes != count) {
            TreeMap<String, Integer> byId = new TreeMap<>();
            for (String id : world.nodeIds()) {
                byId.putIfAbsent(id, number(id));
            }
            sorted = byId.values().stream().mapToInt(Integer::intValue).toArray();
            sortedNodes = count;
        }
        return sorted;
    }

    /**
     * Told by the world that the radio of robot {@code nodeId} went off (the robot was disabled):
     * its links are gone from now on, not from the next refresh.
     */
    public void switchedOff(String nodeId) {
        int n = number(nodeId);   // may grow the tables: number first
        off[n] = true;
    }

    /** Whether the node's radio is on; an id the world does not know (yet) counts as on. */
    private boolean on(int node) {
        if (located[node] == null) {
            node(node);   // first sight of it in the world: reads whether its radio is on
        }
        return !off[node];
    }

    /** The robot or station numbered {@code node}, or null for an unknown id. */
    private RadioGround.Node node(int node) {
        RadioGround.Node at = located[node];
        if (at == null) {
            at = world.node(ids.get(node));   // an id first seen before its robot was added
            locate(node, at);
        }
        return at;
    }

    private void locate(int node, RadioGround.Node at) {
        located[node] = at;
        if (at != null && !at.radioOn()) {
            off[node] = true;
        }
    }

    private int number(String id) {
        Integer known = numbers.get(id);
        if (known != null) {
            return known;
        }
        int n = ids.size();
        if (n == capacity) {
            grow();
        }
        numbers.put(id, n);
        ids.add(id);
        locate(n, world.node(id));
        return n;
    }

    private void grow() {
        int old = capacity;
        capacity = Math.max(16, 2 * old);
        located = Arrays.copyOf(located, capacity);
        x = Arrays.copyOf(x, capacity);
        y = Arrays.copyOf(y, capacity);
        placed = Arrays.copyOf(placed, capacity);
        off = Arrays.copyOf(off, capacity);
        movedIn = Arrays.copyOf(movedIn, capacity);
        double[] oldCache = cache;
        long[] oldComputed = computedIn;
        cache = new double[capacity * capacity];
        computedIn = new long[capacity * capacity];
        for (int i = 0; i < old; i++) {
            System.arraycopy(oldCache, i * old, cache, i * capacity, old);
            System.arraycopy(oldComputed, i * old, computedIn, i * capacity, old);
        }
    }
}
