package net.smc.core.security;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.WeakHashMap;
import java.util.function.BiConsumer;

import net.smc.core.transport.Address;
import net.smc.core.transport.Clock;
import net.smc.core.transport.ForwardingTransport;
import net.smc.core.transport.Receiver;
import net.smc.core.transport.Transport;

/**
 * Authentication as a simulation can afford it: the credential check is real, the per-datagram
 * cryptography is not. In simulation the network itself knows which endpoint sent a datagram (no
 * one can forge a source address of the in-memory network), so once a vehicle's credential has been
 * verified against the trust anchor, everything from its address is vouched for as coming from it.
 * A vehicle whose credential does not verify (a foreign authority, a bad signature, expired, another
 * mission) is never vouched for: what it sends is dropped and counted, exactly as
 * {@link SecureTransport} drops what fails its checks.
 *
 * <p>An adversary can still put anything on the in-memory network ({@code InMemoryNetwork.inject}),
 * with any source address. So that it gains exactly what it would against {@link SecureTransport},
 * every datagram carries a small seal that stands for the real envelope:
 * {@code counter:8 | payload | tag:8}. The counter follows the sender's clock as the real one does
 * ({@code max(last + 1, now << 20)}, kept across restarts); the tag is a keyed 64-bit hash, under a
 * key only this object holds, of the sender's address, the destination (the receiver's address and
 * incarnation for a unicast, as a pair session binds both ends; nothing for a broadcast, as a
 * signature binds no receiver), the counter and the payload. A receiver refuses, and counts:
 * <ul>
 *   <li>what comes from an address with no accepted credential ({@link #dropped()});</li>
 *   <li>a seal whose tag does not match: forged, bit-flipped, sent from another address, or a
 *       unicast meant for an earlier incarnation of the receiver ({@link #tampered()});</li>
 *   <li>a counter whose time lies more than the freshness window (30 s) from the receiver's clock,
 *       or that it accepted before from that sender, by the real {@link ReplayWindow} of 64
 *       counters ({@link #replayed()}).</li>
 * </ul>
 * What it does not model: the handshake's datagrams and their cost, and the cryptography itself
 * (the tag is not a MAC against an adversary that reads this object; the simulated one does not).
 *
 * <p>So this is an ideal {@link SecureTransport}: same delivery rule (only authenticated, fresh,
 * unrepeated payloads, with their proven sender), none of its cost (about 1 ms per Ed25519 signature
 * or verification), which lets thousands of simulated team runs fit in a test run. The real one is
 * exercised by its own tests and by simulation runs that use it.
 *
 * <p>A credential's signature is verified once per JVM and authority key: a simulation that runs
 * the same vehicles many times (a fault sweep, an experiment's runs) checks each credential's
 * signature the first time only, and its validity period and mission every time.
 *
 * <p>Everything kept about one address (its accepted credential, incarnation, seal counter and
 * endpoint) is one {@link Peer}, found by a single look-up per datagram; each endpoint keeps its
 * replay windows in an array indexed by the sender's peer number, so receiving costs one look-up of
 * the sender's address and none for its window.
 *
 * <p>One instance serves one simulated network; all calls on the simulation's thread.
 */
public final class IdealAuthentication {
    /**
     * Credentials whose signature has been verified, with the authority key that verified it: a pure
     * function of the two, so remembered for every instance (weakly: a credential no one holds goes).
     */
    private static final Map<Credential, VerificationKey> SIGNATURES_VERIFIED =
            Collections.synchronizedMap(new WeakHashMap<>());

    private final TrustAnchor trust;
    private final Clock clock;
    /** Every address an endpoint was attached at, with what is known of it. */
    private final Map<Address, Peer> peers = new HashMap<>();
    /** The same, by {@link Peer#index}. */
    private final List<Peer> byIndex = new ArrayList<>();
    private final Map<String, Credential> byVehicle = new HashMap<>();
    private final long key;
    private long dropped;
    private long tampered;
    private long replayed;
    private long ignoredUnverified;
    private long heldUnverified;
    private BiConsumer<Address, Address> heldChecked = (at, from) -> { };

    /** An instance whose tags are keyed by a fixed key (the simulated adversary never reads it). */
    public IdealAuthentication(TrustAnchor trust, Clock clock) {
        this(trust, clock, 0x5DEECE66DL);
    }

    /** @param key the key of the seals' tags */
    public IdealAuthentication(TrustAnchor trust, Clock clock, long key) {
        this.trust = Objects.requireNonNull(trust, "trust");
        this.clock = Objects.requireNonNull(clock, "clock");
        this.key = key;
    }

    /**
     * Wraps a vehicle's endpoint, presenting {@code credential} for it. The credential is checked
     * now; when it fails, the endpoint still sends, but nobody accepts what it sends.
     *
     * @return the endpoint, and whether the credential was accepted
     */
    public Endpoint wrap(Transport inner, Credential credential) {
        Objects.requireNonNull(inner, "inner");
        Objects.requireNonNull(credential, "credential");
        CredentialStatus status = verify(credential);
        Peer peer = peers.computeIfAbsent(inner.localAddress(), this::newPeer);
        if (status == CredentialStatus.VALID) {
            peer.vouched = credential;
            byVehicle.put(credential.vehicleId(), credential);
        } else {
            peer.vouched = null;
        }
        peer.incarnation++;
        Endpoint endpoint = new Endpoint(inner, status, peer);
        peer.endpoint = endpoint;
        return endpoint;
    }

    /**
     * Whether the endpoint at {@code at} drops {@code datagram} (sealed, as the network carries it)
     * before any check, because its receiver would ignore the payload whoever sent it
     * ({@link Endpoint#setUnverifiedFilter}): what a CPU model asks to charge no verification for it.
     * Asked just before the datagram is worked on, it answers what the endpoint will do with it, unless
     * the receiver's state changes in between.
     */
    public boolean dropsUnverified(Address at, byte[] datagram) {
        Peer peer = peers.get(at);
        return peer != null && peer.endpoint.ignorable(datagram);
    }

    /**
     * Whether the endpoint at {@code at} holds {@code datagram} (sealed, as the network carries it)
     * unchecked for its receiver to read first ({@link Endpoint#holdUnverified}): what a CPU model
     * asks to charge no verification and no first contact for it. Asked just before the datagram is
     * worked on, as {@link #dropsUnverified} is.
     */
    public boolean holdsUnverified(Address at, byte[] datagram) {
        Peer peer = peers.get(at);
        return peer != null && peer.endpoint.holdable(datagram);
    }

    /**
     * Tells {@code listener} (the endpoint's address, then the address the datagram came from) each
     * time an endpoint checks a datagram it held ({@link Endpoint#checkHeld}): for a CPU model, the
     * check a real transport does then (the credential and the signature).
     */
    public void onHeldChecked(BiConsumer<Address, Address> listener) {
        this.heldChecked = Objects.requireNonNull(listener, "listener");
    }

    /** {@link TrustAnchor#verify}, with the signature's verification remembered across instances. */
    private CredentialStatus verify(Credential credential) {
        long now = clock.nowMillis();
        if (trust.authority().equals(SIGNATURES_VERIFIED.get(credential))) {
            return trust.checkTimeAndMission(credential, now);
        }
        CredentialStatus status = trust.verify(credential, now);
        if (status != CredentialStatus.FOREIGN_AUTHORITY && status != CredentialStatus.BAD_SIGNATURE) {
            SIGNATURES_VERIFIED.put(credential, trust.authority());
        }
        return status;
    }

    /** Payloads dropped because their sender was not vouched for. */
    public long dropped() {
        return dropped;
    }

    /** Datagrams refused because their seal's tag did not match (forged, altered, re-addressed). */
    public long tampered() {
        return tampered;
    }

    /** Datagrams refused as repeats or as stale (counter outside the freshness window). */
    public long replayed() {
        return replayed;
    }

    /** Datagrams dropped unchecked because their receiver would have ignored them ({@link Endpoint#setUnverifiedFilter}). */
    public long ignoredUnverified() {
        return ignoredUnverified;
    }

    /** Datagrams held unchecked for their receiver to read first ({@link Endpoint#holdUnverified}). */
    public long heldUnverified() {
        return heldUnverified;
    }

    private Peer newPeer(Address address) {
        Peer peer = new Peer(byIndex.size());
        byIndex.add(peer);
        return peer;
    }

    private byte[] seal(Peer from, Address fromAddress, Address to, int toIncarnation, byte[] payload) {
        long counter = Math.max(from.counter + 1, clock.nowMillis() << 20);
        from.counter = counter;
        byte[] out = new byte[payload.length + SEAL_BYTES];
        LONGS.set(out, 0, counter);
        System.arraycopy(payload, 0, out, PAYLOAD_OFFSET, payload.length);
        LONGS.set(out, PAYLOAD_OFFSET + payload.length, tag(fromAddress, to, toIncarnation, counter, payload, 0, payload.length));
        return out;
    }

    /** FNV-1a over the sealed fields, started from and finished with the key (a 64-bit mix). */
    private long tag(Address from, Address to, int toIncarnation, long counter, byte[] data, int offset, int length) {
        long h = key ^ 0xcbf29ce484222325L;
        h = mix(h, from.hashCode());
        h = mix(h, to == null ? 0 : to.hashCode());
        h = mix(h, toIncarnation);
        h = mix(h, counter);
        for (int i = offset; i < offset + length; i++) {
            h = (h ^ (data[i] & 0xff)) * 0x100000001b3L;
        }
        h ^= length;
        h = (h ^ (h >>> 33)) * 0xff51afd7ed558ccdL;
        h = (h ^ (h >>> 33)) * 0xc4ceb9fe1a85ec53L ^ key;
        return h ^ (h >>> 33);
    }

    private static long mix(long h, long value) {
        for (int i = 0; i < 8; i++) {
            h = (h ^ ((value >>> (8 * i)) & 0xff)) * 0x100000001b3L;
        }
        return h;
    }

    /** Big-endian longs in a byte array: the seal's counter and tag. */
    private static final VarHandle LONGS = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);

    /**
     * What is known of one address, over all its endpoints' lives: the credential accepted from it
     * (null when none), how many endpoints were attached there, the last seal counter it used (kept
     * across restarts, as the real sender keeps it) and the endpoint attached there now.
     */
    private static final class Peer {
        /** A small number of its own, from 0: where receivers keep their replay window for it. */
        final int index;
        Credential vouched;
        int incarnation;
        long counter = Long.MIN_VALUE;
        Endpoint endpoint;

        Peer(int index) {
            this.index = index;
        }
    }

    /**
     * Counter and tag, 8 bytes each: a sealed datagram is the counter, the payload from
     * {@link #PAYLOAD_OFFSET}, and the tag.
     */
    public static final int SEAL_BYTES = 16;
    /**
     * Where the payload (the encoded message) starts in a sealed datagram: after the 8-byte counter.
     * For what reads datagrams on the simulated network below this layer (a CPU model charging by
     * message type, say).
     */
    public static final int PAYLOAD_OFFSET = 8;
    private static final long FRESHNESS_MILLIS = SecuritySettings.DEFAULTS.freshnessWindowMillis();
    private static final int REPLAY_WINDOW = SecuritySettings.DEFAULTS.replayWindow();

    /** One vehicle's endpoint: delivers only what vouched-for vehicles sent. */
    public final class Endpoint extends ForwardingTransport implements AuthenticatingTransport {
        private final CredentialStatus status;
        private final int incarnation;
        /** The replay window of each sender heard from, by its {@link Peer#index}; null for one not heard from. */
        private ReplayWindow[] windows = new ReplayWindow[0];
        /** This address's record (its seal counter is shared with its later incarnations). */
        private final Peer self;
        private AuthenticatedReceiver receiver;
        private UnverifiedTest unverifiedFilter = UnverifiedTest.NONE;
        /** The datagrams held unchecked ({@link #holdUnverified}). */
        private final HeldDatagrams held = new HeldDatagrams();
        /** The address this endpoint last sent a unicast to, and its record (a record is never replaced). */
        private Address lastTo;
        private Peer lastToPeer;

        private Endpoint(Transport inner, CredentialStatus status, Peer self) {
            super(inner);
            this.status = status;
            this.incarnation = self.incarnation;
            this.self = self;
            inner.setReceiver(this::onDatagram);
        }

        /** What the network carries less the seal (counter and tag) this endpoint puts round each datagram. */
        @Override
        public int datagramCapacity() {
            return inner.datagramCapacity() - SEAL_BYTES;
        }

        @Override
        public void send(Address to, byte[] data) {
            Peer peer = to == lastTo ? lastToPeer : peers.get(to);
            if (peer != null) {
                lastTo = to;
                lastToPeer = peer;
            }
            inner.send(to, seal(self, localAddress(), to, peer == null ? 0 : peer.incarnation, data));
        }

        @Override
        public void broadcast(byte[] data) {
            inner.broadcast(seal(self, localAddress(), null, 0, data));
        }

        /** As {@link #send}: this layer makes no sessions (the CPU model charges the signature). */
        @Override
        public void sendWithoutHandshake(Address to, byte[] data) {
            send(to, data);
        }

        /**
         * As {@link SecureTransport#holdUnverified}, for every datagram (this layer has no sessions):
         * one whose payload {@code readable} accepts is held before any check, its payload handed to
         * {@code receiver}, and checked when {@link #checkHeld} asks.
         */
        @Override
        public void holdUnverified(UnverifiedTest readable, UnverifiedReceiver receiver) {
            held.set(readable, receiver);
        }

        @Override
        public boolean checkHeld(Address from) {
            return held.check(from, data -> {
                heldChecked.accept(localAddress(), from);
                check(from, data);
            });
        }

        /** Whether {@code data} (sealed) carries a payload the receiver reads before it is checked. */
        boolean holdable(byte[] data) {
            return data.length >= SEAL_BYTES && held.accepts(data, PAYLOAD_OFFSET, data.length - SEAL_BYTES);
        }

        /** What the check of this endpoint's own credential found. */
        public CredentialStatus credentialStatus() {
            return status;
        }

        @Override
        public void setReceiver(Receiver plain) {
            Objects.requireNonNull(plain, "receiver");
            setAuthenticatedReceiver((sender, from, protection, payload) -> plain.onDatagram(from, payload));
        }

        @Override
        public void setAuthenticatedReceiver(AuthenticatedReceiver receiver) {
            if (this.receiver != null) {
                throw new IllegalStateException("a receiver is already set on the endpoint at " + localAddress());
            }
            this.receiver = Objects.requireNonNull(receiver, "receiver");
        }

        @Override
        public Optional<Credential> credentialOf(String peer) {
            return Optional.ofNullable(byVehicle.get(peer));
        }

        /**
         * As {@link SecureTransport#setUnverifiedFilter}: a datagram whose payload the receiver would
         * ignore is dropped before any check (where the real transport drops a signed one before its
         * signature verification), and counted ({@link #ignoredUnverified()}).
         */
        @Override
        public void setUnverifiedFilter(UnverifiedTest ignorable) {
            this.unverifiedFilter = Objects.requireNonNull(ignorable, "ignorable");
        }

        /** Whether {@code data} (sealed) carries a payload the receiver would ignore: read, not checked. */
        boolean ignorable(byte[] data) {
            return data.length >= SEAL_BYTES
                    && unverifiedFilter.test(data, PAYLOAD_OFFSET, data.length - SEAL_BYTES);
        }

        private void onDatagram(Address from, byte[] data) {
            if (ignorable(data)) {
                ignoredUnverified++;
                return;
            }
            if (holdable(data)) {
                heldUnverified++;
                held.hold(from, data, Arrays.copyOfRange(data, PAYLOAD_OFFSET, PAYLOAD_OFFSET + data.length - SEAL_BYTES));
                return;
            }
            check(from, data);
        }

        /** Every check of a datagram that is neither dropped nor held unchecked, then its delivery. */
        private void check(Address from, byte[] data) {
            Peer peer = peers.get(from);
            Credential sender = peer == null ? null : peer.vouched;
            if (sender == null || receiver == null) {
                dropped++;
                return;
            }
            if (data.length < SEAL_BYTES) {
                tampered++;
                return;
            }
            long counter = (long) LONGS.get(data, 0);
            long tag = (long) LONGS.get(data, data.length - 8);
            int length = data.length - SEAL_BYTES;
            if (tag != tag(from, localAddress(), incarnation, counter, data, 8, length)
                    && tag != tag(from, null, 0, counter, data, 8, length)) {
                tampered++;
                return;
            }
            ReplayWindow window = windowOf(peer);
            long sentMillis = counter >> 20;
            if (Math.abs(clock.nowMillis() - sentMillis) > FRESHNESS_MILLIS || !window.isFresh(counter)) {
                replayed++;
                return;
            }
            window.mark(counter, sentMillis);
            receiver.onMessage(sender.vehicleId(), from, Protection.PAIR_MAC,
                    Arrays.copyOfRange(data, PAYLOAD_OFFSET, PAYLOAD_OFFSET + length));
        }

        private ReplayWindow windowOf(Peer sender) {
            if (sender.index >= windows.length) {
                windows = Arrays.copyOf(windows, Math.max(sender.index + 1, Math.min(byIndex.size(), 2 * windows.length)));
            }
            ReplayWindow window = windows[sender.index];
            if (window == null) {
                window = new ReplayWindow(REPLAY_WINDOW);
                windows[sender.index] = window;
            }
            return window;
        }
    }
}
