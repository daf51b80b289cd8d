package net.smc.core.comm;

import java.util.HashMap;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.random.RandomGenerator;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import net.smc.core.message.Ack;
import net.smc.core.message.Acks;
import net.smc.core.message.Envelope;
import net.smc.core.message.Message;
import net.smc.core.message.MessageType;
import net.smc.core.message.ReassemblySettings;
import net.smc.core.message.SharedDecodes;
import net.smc.core.router.MessageRouter;
import net.smc.core.security.AuthenticatingTransport;
import net.smc.core.transport.Address;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Scheduler;
import net.smc.core.transport.Transport;

/**
 * The Communication-Manager of the paper (section IV-A): a cell's single point of sending and
 * receiving. Ordinary traffic goes out connectionless (one datagram, or its fragments, once);
 * messages of the {@link CriticalTypes critical types} go through the {@link MessageSender}, which
 * acknowledges, retransmits and reports failures. Every message leaves with this cell's vehicle id
 * as sender and a fresh id, increasing per cell.
 *
 * <p>Incoming datagrams are decoded (a bad one is counted and logged at debug level, never thrown),
 * Acks (single or coalesced) are consumed, critical messages are acknowledged (coalesced per
 * burst, see {@link MessageSender}) and de-duplicated, and each application
 * message is handed once to the {@link MessageRouter}. Connectionless messages keep UDP's
 * semantics: one may be lost or, if the network duplicates it, dispatched twice.
 *
 * <p>On an {@link AuthenticatingTransport} the envelope's sender must be the proven sender: a
 * message whose envelope names another vehicle is dropped and counted as spoofed. There the headers
 * of the types chosen with {@link Builder#senderLeftToTransport} leave the sender out, and the
 * receiving side takes the proven one. Either way the
 * manager remembers the address each vehicle last sent from ({@link #addressOf}), so that replies
 * and protocols can name peers by vehicle id.
 *
 * <p>Sans-IO: it uses only the given clock, scheduler and transport, and must be called on the
 * cell's thread (in deployment, submit to the cell's executor). A pair of simulated cells:
 * <pre>{@code
 * SimulationScheduler sim = new SimulationScheduler();
 * InMemoryNetwork net = new InMemoryNetwork(sim, 7);
 * MessageRouter router = new MessageRouter();
 * List<Envelope> assignments = new ArrayList<>();
 * router.register(assignments::add, MessageType.ROLE_ASSIGNMENT);
 * CommunicationManager a = CommunicationManager.builder("uav-a", net.attach(Address.loopback(4001)), sim, sim)
 *         .random(new SplittableRandom(1)).router(new MessageRouter()).build();
 * CommunicationManager b = CommunicationManager.builder("uav-b", net.attach(Address.loopback(4002)), sim, sim)
 *         .random(new SplittableRandom(2)).router(router).build();
 * a.start(); b.start();
 * a.send(Address.loopback(4002), assignment, listener);   sim.runUntilIdle(10_000);
 * }</pre>
 * See <a href="doc-files/reliable-delivery.md">the reliable-delivery design note</a>.
 */
public final class CommunicationManager {
    private static final Logger log = LoggerFactory.getLogger(CommunicationManager.class);

    private final String vehicleId;
    private final Transport transport;
    private final MessageRouter router;
    private final CriticalTypes critical;
    private final DeliveryListener defaultListener;
    private final CommCounters counters = new CommCounters();
    private final Wire wire;
    private final IdSource ids;
    private final MessageSender sender;
    private final Map<String, Address> addresses = new HashMap<>();
    /**
     * Recent (sender, address) pairs already in {@link #addresses}, one place per sender by the hash
     * of its name: a datagram from the same sender object at the same address object needs no write
     * to the map. A pair is held only while the map gives that sender that address: only
     * {@link #learn} replaces a sender's address, and it replaces the sender's place here too.
     */
    private final String[] learnedSenders = new String[LEARNED_PLACES];
    private final Address[] learnedAddresses = new Address[LEARNED_PLACES];
    private static final int LEARNED_PLACES = 16;
    private boolean started;
    private boolean stopped;

    private CommunicationManager(Builder b) {
        this.vehicleId = b.vehicleId;
        this.transport = b.transport;
        this.router = b.router;
        this.critical = b.critical;
        this.defaultListener = b.listener;
        this.wire = new Wire(b.transport, b.clock, b.reassembly, counters, b.sharedDecodes,
                b.transport instanceof AuthenticatingTransport ? b.senderLeft : Set.of());
        this.ids = new IdSource(b.clock);
        this.sender = new MessageSender(b.vehicleId, b.clock, b.scheduler, b.random, b.settings, wire, ids);
    }

    /**
     * A builder for the cell {@code vehicleId} on {@code transport}, with its clock and scheduler;
     * the random source and the router are required too.
     */
    public static Builder builder(String vehicleId, Transport transport, Clock clock, Scheduler scheduler) {
        return new Builder(vehicleId, transport, clock, scheduler);
    }

    /** Registers as the transport's receiver: from now on datagrams are decoded and dispatched. */
    public void start() {
        if (started) {
            throw new IllegalStateException("communication manager of '" + vehicleId + "' is already started");
        }
        started = true;
        if (transport instanceof AuthenticatingTransport authenticating) {
            authenticating.setAuthenticatedReceiver((proven, from, protection, data) -> onDatagram(proven, from, data));
        } else {
            transport.setReceiver(this::onDatagram);
        }
    }

    /** Whether senders are proven by the transport rather than claimed by the envelope. */
    public boolean authenticated() {
        return transport instanceof AuthenticatingTransport;
    }

    /** The address vehicle {@code vehicle} last sent a message from, if it has sent one. */
    public Optional<Address> addressOf(String vehicle) {
        return Optional.ofNullable(addresses.get(vehicle));
    }

    /** Teaches the address of a vehicle this cell has not heard from yet (a replicated roster, say). */
    public void learnAddress(String vehicle, Address address) {
        addresses.putIfAbsent(Objects.requireNonNull(vehicle, "vehicle"), Objects.requireNonNull(address, "address"));
    }

    /**
     * Stops the Message-Sender (outstanding critical messages are reported failed, as
     * {@link FailureReason#STOPPED}) and ignores what arrives later. The transport belongs to the
     * caller, who closes it.
     */
    public void stop() {
        stopped = true;
        sender.stop();
    }

    /**
     * Sends {@code message} to {@code to}: reliably when its type is critical (the outcome goes to
     * the builder's default listener), connectionless otherwise.
     *
     * @return the message's id
     */
    public long send(Address to, Message message) {
        Objects.requireNonNull(to, "to");
        Objects.requireNonNull(message, "message");
        if (critical.contains(message.type())) {
            return sender.send(to, message, defaultListener);
        }
        checkRunning(message);
        long id = ids.next();
        wire.send(to, wire.encode(new Envelope(vehicleId, id, message)));
        counters.unicasts++;
        return id;
    }

    /**
     * Sends {@code message} to {@code to} connectionless and, on an {@link AuthenticatingTransport},
     * without starting a session ({@link AuthenticatingTransport#sendWithoutHandshake}): for a message
     * its receiver reads before checking it, and answers, if at all, by contacting this cell (a
     * discovery reply).
     *
     * @return the message's id
     * @throws IllegalArgumentException when the type is critical: its acknowledgement would need the session
     */
    public long sendWithoutHandshake(Address to, Message message) {
        Objects.requireNonNull(to, "to");
        Objects.requireNonNull(message, "message");
        if (critical.contains(message.type())) {
            throw new IllegalArgumentException(message.type() + " to " + to + " is a critical type; it goes reliably"
                    + " (send), under a session, not without a handshake");
        }
        checkRunning(message);
        long id = ids.next();
        wire.sendWithoutHandshake(to, wire.encode(new Envelope(vehicleId, id, message)));
        counters.unicasts++;
        return id;
    }

    /**
     * Sends a critical message to {@code to} reliably; {@code listener} learns whether it was
     * acknowledged or given up on.
     *
     * @return the message's id, as named by the listener's calls
     * @throws IllegalArgumentException when the type is not critical: the receiver would not acknowledge it
     */
    public long send(Address to, Message message, DeliveryListener listener) {
        Objects.requireNonNull(to, "to");
        Objects.requireNonNull(message, "message");
        Objects.requireNonNull(listener, "listener");
        if (!critical.contains(message.type())) {
            throw new IllegalArgumentException(message.type() + " to " + to + " cannot be sent reliably: it is not"
                    + " a critical type, so the receiver would never acknowledge it; critical types are "
                    + critical.types() + " (the same set on every cell)");
        }
        return sender.send(to, message, listener);
    }

    /**
     * Broadcasts {@code message} to every cell in reach, connectionless.
     *
     * @return the message's id
     * @throws IllegalArgumentException when the type is critical: a broadcast has no one receiver to acknowledge it
     */
    public long broadcast(Message message) {
        Objects.requireNonNull(message, "message");
        if (critical.contains(message.type())) {
            throw new IllegalArgumentException(message.type() + " cannot be broadcast: it is a critical type and"
                    + " needs one receiver to acknowledge it; send it to each cell instead");
        }
        checkRunning(message);
        long id = ids.next();
        wire.broadcast(wire.encode(new Envelope(vehicleId, id, message)));
        counters.broadcasts++;
        return id;
    }

    /**
     * How long from now until what this cell has handed to its transport has left it
     * ({@link Transport#backlogMillis()}): a request sent now leaves then, and a round trip is
     * measured from then.
     */
    public long backlogMillis() {
        return transport.backlogMillis();
    }

    /** The vehicle id every message of this cell carries as its sender. */
    public String vehicleId() {
        return vehicleId;
    }

    /** Where other cells reach this one. */
    public Address localAddress() {
        return transport.localAddress();
    }

    public CriticalTypes critical() {
        return critical;
    }

    /** The reliable half: its counters, settings and outstanding messages. */
    public MessageSender sender() {
        return sender;
    }

    public CommCounters counters() {
        return counters;
    }

    /** One datagram from the transport, on the cell's thread. */
    void onDatagram(Address from, byte[] data) {
        onDatagram(null, from, data);
    }

    /** One datagram; {@code proven} is its authenticated sender, or null on a plain transport. */
    private void onDatagram(String proven, Address from, byte[] data) {
        if (stopped) {
            return;
        }
        Envelope envelope = wire.decode(proven, from, data);
        if (envelope == null) {
            return;
        }
        if (proven != null && !proven.equals(envelope.sender())) {
            counters.spoofed++;
            log.debug("'{}': dropped {} from {} claiming to be '{}' but authenticated as '{}'", vehicleId,
                    envelope.type(), from, envelope.sender(), proven);
            return;
        }
        learn(envelope.sender(), from);
        Message body = envelope.body();
        if (body instanceof Ack ack) {
            counters.acksReceived++;
            sender.acknowledged(from, ack);
            return;
        }
        if (body instanceof Acks acks) {
            counters.acksReceived++;
            sender.acknowledged(from, acks);
            return;
        }
        if (!critical.contains(body.type())) {
            dispatch(envelope);
            return;
        }
        if (sender.admit(envelope)) {
            dispatch(envelope);
        }
        sender.acknowledge(from, envelope);
    }

    /** Records that {@code sender} sent from {@code from}: the address replies go to. */
    private void learn(String sender, Address from) {
        int place = sender.hashCode() & LEARNED_PLACES - 1;
        if (learnedSenders[place] == sender && learnedAddresses[place] == from) {
            return;   // the map holds this pair already
        }
        addresses.put(sender, from);
        learnedSenders[place] = sender;
        learnedAddresses[place] = from;
    }

    private void dispatch(Envelope envelope) {
        counters.dispatched++;
        router.dispatch(envelope);
    }

    private void checkRunning(Message message) {
        if (stopped) {
            throw new IllegalStateException("communication manager of '" + vehicleId + "' is stopped; cannot send "
                    + message.type());
        }
    }

    @Override
    public String toString() {
        return "CommunicationManager[" + vehicleId + " at " + transport.localAddress() + "]";
    }

    /** Collects what a {@link CommunicationManager} needs; each setter checks its argument. */
    public static final class Builder {
        private final String vehicleId;
        private final Transport transport;
        private final Clock clock;
        private final Scheduler scheduler;
        private RandomGenerator random;
        private MessageRouter router;
        private SenderSettings settings = SenderSettings.DEFAULTS;
        private CriticalTypes critical = CriticalTypes.DEFAULT;
        private ReassemblySettings reassembly = ReassemblySettings.DEFAULTS;
        private DeliveryListener listener;
        private SharedDecodes sharedDecodes;
        private Set<MessageType> senderLeft = Set.of();

        private Builder(String vehicleId, Transport transport, Clock clock, Scheduler scheduler) {
            if (vehicleId == null || vehicleId.isEmpty()) {
                throw new IllegalArgumentException("vehicle id is " + (vehicleId == null ? "null" : "empty")
                        + "; every message needs its sender's vehicle id");
            }
            this.vehicleId = vehicleId;
            this.transport = Objects.requireNonNull(transport, "transport");
            this.clock = Objects.requireNonNull(clock, "clock");
            this.scheduler = Objects.requireNonNull(scheduler, "scheduler");
            this.listener = new LoggingListener(vehicleId);
        }

        /**
         * Shares the decodes of broadcast datagrams with the other cells of this process given the
         * same table (default: none), for simulations of many cells in one process.
         */
        public Builder sharedDecodes(SharedDecodes table) {
            this.sharedDecodes = table;
            return this;
        }

        /**
         * On an authenticating transport, the message types whose header leaves the sender out, to
         * be named by the receiver's transport, which proves it (default: none; on a plain transport
         * every header names its sender whatever is set here). A receiver reads such a message only
         * from its authenticated receiver, so leave out the types no receiver reads before the
         * transport's checks. Must be the same on every cell, as the critical types are.
         */
        public Builder senderLeftToTransport(Set<MessageType> types) {
            this.senderLeft = Set.copyOf(types);
            return this;
        }

        /** The random source of the retransmission jitter (seeded in simulation). Required. */
        public Builder random(RandomGenerator random) {
            this.random = Objects.requireNonNull(random, "random");
            return this;
        }

        /** The Message-Router that receives every application message. Required. */
        public Builder router(MessageRouter router) {
            this.router = Objects.requireNonNull(router, "router");
            return this;
        }

        /** Retransmission and duplicate-window settings; {@link SenderSettings#DEFAULTS} if not set. */
        public Builder settings(SenderSettings settings) {
            this.settings = Objects.requireNonNull(settings, "settings");
            return this;
        }

        /** The critical types; {@link CriticalTypes#DEFAULT} if not set. Must be the same on every cell. */
        public Builder critical(CriticalTypes critical) {
            this.critical = Objects.requireNonNull(critical, "critical");
            return this;
        }

        /** Fragment reassembly limits of the decoder; {@link ReassemblySettings#DEFAULTS} if not set. */
        public Builder reassembly(ReassemblySettings reassembly) {
            this.reassembly = Objects.requireNonNull(reassembly, "reassembly");
            return this;
        }

        /** Told the outcome of critical messages sent without a listener of their own; by default failures are logged. */
        public Builder listener(DeliveryListener listener) {
            this.listener = Objects.requireNonNull(listener, "listener");
            return this;
        }

        public CommunicationManager build() {
            if (random == null || router == null) {
                throw new IllegalStateException("communication manager of '" + vehicleId + "' needs "
                        + (random == null ? "a random source (random(...))" : "")
                        + (random == null && router == null ? " and " : "")
                        + (router == null ? "a message router (router(...))" : ""));
            }
            return new CommunicationManager(this);
        }
    }

    /**
     * The default listener: a critical message given up on is worth a warning; one still out when
     * the cell was stopped is not (stopping is the cell's owner's choice), and is logged at debug.
     */
    private record LoggingListener(String vehicleId) implements DeliveryListener {
        @Override
        public void failed(long id, FailureReason reason) {
            if (reason == FailureReason.STOPPED) {
                log.debug("'{}': critical message {} still out when the cell stopped", vehicleId, id);
            } else {
                log.warn("'{}': critical message {} was not delivered: {}", vehicleId, id, reason);
            }
        }
    }
}
