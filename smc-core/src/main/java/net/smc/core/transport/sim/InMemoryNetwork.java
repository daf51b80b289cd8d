package net.smc.core.transport.sim;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.NavigableMap;
import java.util.Objects;
import java.util.Set;
import java.util.TreeMap;
import java.util.random.RandomGenerator;
import java.util.random.RandomGeneratorFactory;

import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;

/**
 * A simulated radio network on a {@link SimulationScheduler}: nodes attach and get a
 * {@link Transport}; datagrams travel with per-link latency, jitter, loss, duplication and
 * re-ordering ({@link LinkProfile}), can be cut by partitions and by a {@link RadioModel}, and are
 * lost with a node that crashes. One seed gives one run: the same sends give the same deliveries at
 * the same times, to the byte.
 *
 * <p>The fate of each copy is decided when it is sent (partition, radio reach, loss, delay,
 * duplicate), in this order, with random draws in a fixed order ({@link Links}); whether anyone is
 * there to take it is decided when it arrives. A broadcast makes one copy for every other attached
 * node, in ascending address order. Every copy is counted once, as delivered or under the reason it
 * was dropped ({@link NodeCounters}), and reported to the {@link NetworkObserver}s.
 *
 * <p>Single-threaded, like the scheduler it runs on. See
 * <a href="../doc-files/transport.md">the transport design note</a>.
 */
public final class InMemoryNetwork {
    private final SimulationScheduler scheduler;
    private final Links links;
    private final Partitions partitions = new Partitions();
    private final NavigableMap<Address, SimTransport> attached = new TreeMap<>();
    /** The same as {@link #attached}, for look-ups by hash (a copy's arrival) rather than by order. */
    private final Map<Address, SimTransport> attachedByHash = new HashMap<>();
    /** {@link #attached}'s addresses in order, for broadcasts; null when attaches or detaches made it stale. */
    private Address[] broadcastOrder;
    private final Set<Address> crashed = new HashSet<>();                 // looked up only
    private final Map<Address, Counters> counters = new HashMap<>();      // looked up, or summed
    private final List<NetworkObserver> observers = new ArrayList<>();
    private RadioModel radio = RadioModel.EVERYONE;
    private CpuModel cpu;                                                 // null: handled on arrival, at no cost
    private long bytesPerSecond;                                          // 0: no serialisation delay
    private final Map<Address, NodeCpu> cpus = new HashMap<>();           // looked up only

    /**
     * A network whose random draws come from a {@code L64X128MixRandom} generator seeded with
     * {@code seed} (an algorithm fixed by the JDK, so a seed means the same run on every JVM).
     */
    public InMemoryNetwork(SimulationScheduler scheduler, long seed) {
        this(scheduler, RandomGeneratorFactory.of("L64X128MixRandom").create(seed));
    }

    /** A network drawing from {@code random}; it must be seeded for runs to replay. */
    public InMemoryNetwork(SimulationScheduler scheduler, RandomGenerator random) {
        this.scheduler = Objects.requireNonNull(scheduler, "scheduler");
        this.links = new Links(random);
    }

    /**
     * Attaches a node at {@code address} and returns its endpoint.
     *
     * @throws IllegalArgumentException when a node is attached there already
     */
    public Transport attach(Address address) {
        Objects.requireNonNull(address, "address");
        if (attached.containsKey(address)) {
            throw new IllegalArgumentException("address " + address + " is already attached; close or crash its node first");
        }
        crashed.remove(address);
        SimTransport transport = new SimTransport(this, address, countersOf(address));
        attached.put(address, transport);
        attachedByHash.put(address, transport);
        broadcastOrder = null;
        return transport;
    }

    /**
     * Crashes the node at {@code address}: it is detached without being told. What it sends from
     * now on is dropped ({@link DropReason#SENDER_DOWN}); what arrives for it is dropped
     * ({@link DropReason#RECEIVER_DOWN}); broadcasts leave it out. Copies already in flight from it
     * still arrive, as they would on a real network. Its timers are the simulation's to stop
     * (see {@link net.smc.core.transport.TimerGroup}).
     *
     * @throws IllegalArgumentException when no node is attached there
     */
    public void crash(Address address) {
        SimTransport transport = attached.remove(Objects.requireNonNull(address, "address"));
        if (transport == null) {
            throw new IllegalArgumentException("no node is attached at " + address + "; only an attached node can crash");
        }
        attachedByHash.remove(address);
        broadcastOrder = null;
        transport.crash();
        crashed.add(address);
    }

    /**
     * Restarts a crashed node: a new endpoint at the same address, as a rebooted vehicle gets. The
     * old endpoint stays dead.
     *
     * @throws IllegalArgumentException when the node at {@code address} has not crashed
     */
    public Transport restart(Address address) {
        if (!crashed.contains(Objects.requireNonNull(address, "address"))) {
            throw new IllegalArgumentException("node " + address + " has not crashed; only a crashed node can restart");
        }
        return attach(address);
    }

    /**
     * Puts a datagram on the air as an adversary does: it claims to come from {@code from} (a UDP
     * source can be forged) and reaches {@code to} after {@code delayMillis}, past partitions, the
     * radio and loss. Counted as delivered (or dropped on arrival) like any copy, and seen by observers.
     */
    public void inject(Address from, Address to, byte[] data, long delayMillis) {
        Objects.requireNonNull(from, "from");
        Objects.requireNonNull(to, "to");
        byte[] copy = data.clone();
        scheduler.schedule(Math.max(0, delayMillis), () -> arrive(from, to, copy, true));
    }

    /** Cuts every link between a node of {@code sideA} and a node of {@code sideB}, both ways, until {@link #heal()}. */
    public void partition(Set<Address> sideA, Set<Address> sideB) {
        partitions.add(sideA, sideB);
    }

    /** Removes every partition. */
    public void heal() {
        partitions.healAll();
    }

    /** Sets the profile of every link that has no profile of its own. */
    public void setDefaultLink(LinkProfile profile) {
        links.setDefault(profile);
    }

    /** Sets the profile of the directed link from {@code from} to {@code to} (the other way is separate). */
    public void setLink(Address from, Address to, LinkProfile profile) {
        links.set(from, to, profile);
    }

    /** Forgets every link's own profile; all links use the default again. */
    public void clearLinks() {
        links.clearOverrides();
    }

    /** Sets the radio model, asked for every copy sent from now on. */
    public void setRadio(RadioModel radio) {
        this.radio = Objects.requireNonNull(radio, "radio");
    }

    /**
     * Charges every node's CPU for the datagrams it sends and receives, from now on: a node handles
     * its next datagram no earlier than its CPU is free, and what it sends leaves when the work of
     * sending is done. Without a model (the default) datagrams are handled as they arrive.
     */
    public void setCpuModel(CpuModel model) {
        this.cpu = Objects.requireNonNull(model, "model");
    }

    /**
     * Gives every node's radio a transmission rate: a datagram of {@code n} bytes occupies its
     * sender's transmitter for {@code n / bytesPerSecond} seconds (a broadcast once), and datagrams
     * queue behind each other. 0, the default, sends instantly. Needs a {@link CpuModel}
     * ({@link CpuModel#FREE} will do); the shared medium's contention between senders is not modelled.
     */
    public void setBandwidth(long bytesPerSecond) {
        if (bytesPerSecond < 0) {
            throw new IllegalArgumentException("bandwidth of " + bytesPerSecond + " bytes/s is negative; it must be 0 (none) or more");
        }
        if (bytesPerSecond > 0 && cpu == null) {
            throw new IllegalStateException("a bandwidth needs a CPU model; set one first (CpuModel.FREE for none)");
        }
        this.bytesPerSecond = bytesPerSecond;
    }

    /** The CPU time charged to the node at {@code address} by the {@link CpuModel}, in microseconds. */
    public long cpuMicros(Address address) {
        NodeCpu c = cpus.get(address);
        return c == null ? 0 : c.chargedMicros;
    }

    /** Adds an observer; observers are told in the order they were added. */
    public void addObserver(NetworkObserver observer) {
        observers.add(Objects.requireNonNull(observer, "observer"));
    }

    /** The attached nodes in ascending order: a read-only view that follows attaches, crashes and closes. */
    public Set<Address> attached() {
        return Collections.unmodifiableSet(attached.navigableKeySet());
    }

    /** What the network did for {@code address}, over all its node's lives; zeros if nothing. */
    public NodeCounters counters(Address address) {
        Counters c = counters.get(address);
        return c == null ? NodeCounters.ZERO : c.snapshot();
    }

    /** The sum of every address's counters. */
    public NodeCounters totals() {
        NodeCounters sum = NodeCounters.ZERO;
        for (Counters c : counters.values()) {
            sum = sum.plus(c.snapshot());
        }
        return sum;
    }

    // ---- called by SimTransport ----

    void send(SimTransport sender, Address to, byte[] data) {
        sender.counters.sent++;
        observeSent(sender, to, data);
        route(sender, to, data, departureDelay(sender, to, data), false);
    }

    void broadcast(SimTransport sender, byte[] data) {
        sender.counters.sent++;
        observeSent(sender, null, data);
        long delay = departureDelay(sender, null, data);
        if (broadcastOrder == null) {
            broadcastOrder = attached.keySet().toArray(new Address[0]);
        }
        Address self = sender.localAddress();
        for (Address to : broadcastOrder) {   // route never attaches or detaches
            if (!to.equals(self)) {
                route(sender, to, data, delay, true);
            }
        }
    }

    private void observeSent(SimTransport sender, Address to, byte[] data) {
        if (!sender.isCrashed()) {
            for (NetworkObserver o : observers) {
                o.sent(scheduler.nowMillis(), sender.localAddress(), to, data);
            }
        }
    }

    /** With a CPU model: charges the sender and tells how many ms from now the datagram leaves. */
    private long departureDelay(SimTransport sender, Address to, byte[] data) {
        if (cpu == null || sender.isCrashed()) {
            return 0;
        }
        Address from = sender.localAddress();
        NodeCpu node = sender.cpu != null ? sender.cpu : (sender.cpu = cpuOf(from));
        long now = scheduler.nowMillis() * 1_000;
        long ready = node.charge(now, cpu.sendMicros(from, to, data));
        long out = bytesPerSecond == 0 ? ready : node.transmit(ready, cpu.airBytes(from, to, data), bytesPerSecond);
        node.lastDepartureMicros = Math.max(node.lastDepartureMicros, out);
        return floorMillis(out) - scheduler.nowMillis();
    }

    /**
     * Milliseconds from now until the last datagram {@code sender} sent leaves its node, as
     * {@link #departureDelay} reckons it: 0 without a CPU model, or when it has left.
     */
    long backlogMillis(SimTransport sender) {
        NodeCpu node = sender.cpu;
        if (cpu == null || node == null || sender.isCrashed()) {
            return 0;
        }
        return Math.max(0, floorMillis(node.lastDepartureMicros) - scheduler.nowMillis());
    }

    void detach(SimTransport transport) {
        if (attached.remove(transport.localAddress(), transport)) {
            attachedByHash.remove(transport.localAddress());
            broadcastOrder = null;
        }
    }

    // ---- one copy's fate ----

    private void route(SimTransport sender, Address to, byte[] data, long departureMillis, boolean broadcast) {
        Address from = sender.localAddress();
        sender.counters.copies++;
        if (sender.isCrashed()) {
            drop(from, to, DropReason.SENDER_DOWN, data, from);
            return;
        }
        if (partitions.separates(from, to)) {
            drop(from, to, DropReason.PARTITION, data, to);
            return;
        }
        if (!radio.reachable(from, to)) {
            drop(from, to, DropReason.RADIO, data, to);
            return;
        }
        LinkProfile profile = links.profile(from, to);
        if (links.lost(profile)) {
            drop(from, to, DropReason.LOSS, data, to);
            return;
        }
        long delay = links.delayMillis(profile);
        boolean duplicated = links.duplicated(profile);   // drawn after the first copy's delay, as always
        // A unicast's bytes are the network's own (the sender's transport copied them): its one copy
        // takes them. A broadcast's are shared by every copy, and a duplicate's by two.
        scheduleArrival(from, to, data, departureMillis + delay, broadcast, !broadcast && !duplicated);
        if (duplicated) {
            sender.counters.copies++;
            countersOf(to).duplicated++;
            scheduleArrival(from, to, data, departureMillis + links.delayMillis(profile), broadcast, false);
        }
    }

    /** @param owned whether the copy may hand {@code data} itself to its receiver (no other copy shares it) */
    private void scheduleArrival(Address from, Address to, byte[] data, long delayMillis, boolean broadcast, boolean owned) {
        if (cpu == null) {
            scheduler.schedule(delayMillis, () -> arrive(from, to, data, owned));
        } else {
            scheduler.schedule(delayMillis, () -> queue(from, to, data, broadcast));
        }
    }

    // ---- with a CPU model: an inbox per node, one datagram worked on at a time ----

    private void queue(Address from, Address to, byte[] data, boolean broadcast) {
        NodeCpu node = cpuOf(to);
        node.inbox.addLast(new NodeCpu.Waiting(from, data, broadcast, scheduler.nowMillis() * 1_000));
        if (!node.draining) {
            node.draining = true;
            scheduler.schedule(untilMillis(node.busyUntilMicros), () -> work(to, node));
        }
    }

    /**
     * The CPU is free: it takes the oldest waiting datagram, and the cell gets it when the work is
     * done. Times are kept in microseconds and the cell acts in the millisecond the work ends in
     * (the clock's resolution), so that costs below a millisecond add up without rounding.
     */
    private void work(Address at, NodeCpu node) {
        NodeCpu.Waiting w = node.inbox.pollFirst();
        long done = node.charge(w.arrivedMicros(), cpu.receiveMicros(at, w.from(), w.data(), w.broadcast()));
        scheduler.schedule(untilMillis(done), () -> {
            arrive(w.from(), at, w.data(), false);
            if (node.inbox.isEmpty()) {
                node.draining = false;
            } else {
                scheduler.schedule(untilMillis(node.busyUntilMicros), () -> work(at, node));
            }
        });
    }

    /** Milliseconds from now to the millisecond that holds {@code micros} (0 when it is now or past). */
    private long untilMillis(long micros) {
        return Math.max(0, floorMillis(micros) - scheduler.nowMillis());
    }

    private NodeCpu cpuOf(Address address) {
        return cpus.computeIfAbsent(address, a -> new NodeCpu());
    }

    private static long floorMillis(long micros) {
        return Math.floorDiv(micros, 1_000);
    }

    /** @param owned whether {@code data} is this copy's alone, to hand over as it is; else the receiver gets a copy */
    private void arrive(Address from, Address to, byte[] data, boolean owned) {
        SimTransport destination = attachedByHash.get(to);
        if (destination == null) {
            drop(from, to, DropReason.RECEIVER_DOWN, data, to);
        } else if (!destination.hasReceiver()) {
            drop(from, to, DropReason.NO_RECEIVER, data, to);
        } else {
            destination.counters.delivered++;
            byte[] copy = owned ? data : data.clone();   // each copy is the receiver's own to keep or change
            for (NetworkObserver o : observers) {
                o.delivered(scheduler.nowMillis(), from, to, copy);
            }
            destination.deliver(from, copy);
        }
    }

    private void drop(Address from, Address to, DropReason reason, byte[] data, Address countedAt) {
        countersOf(countedAt).dropped(reason);
        for (NetworkObserver o : observers) {
            o.dropped(scheduler.nowMillis(), from, to, reason, data);
        }
    }

    private Counters countersOf(Address address) {
        return counters.computeIfAbsent(address, a -> new Counters());
    }
}
