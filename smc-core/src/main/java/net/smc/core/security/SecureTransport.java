package net.smc.core.security;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import net.smc.core.transport.Address;
import net.smc.core.transport.Receiver;
import net.smc.core.transport.Transport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A {@link Transport} that authenticates everything it carries, so that a cell written against
 * {@code Transport} gets authentication by being handed this instead of the bare transport.
 *
 * <ul>
 *   <li>{@link #broadcast}: signed (discovery must reach vehicles that hold no team key yet);
 *       {@link #teamBroadcast}: under the team key.</li>
 *   <li>{@link #send}: MAC'd under the session with the vehicle at that address; signed while there
 *       is none, and then a handshake goes along with it, so sessions form by themselves.</li>
 *   <li>Arriving datagrams are unwrapped; payloads go to the receiver, handshake answers go back to
 *       their sender, refusals are counted by the endpoint. When a peer MACs under a session this
 *       side has lost (it restarted), a handshake goes back to it, at most
 *       {@value #PROBES_PER_RETRY} such per handshake-retry interval in all.</li>
 * </ul>
 *
 * Signed datagrams (whose check costs an Ed25519 verification) are checked within a budget per
 * source address and in all ({@link SignatureBudget}); beyond it they are dropped unchecked and
 * counted ({@link #droppedOverBudget}). Before that, a signed datagram whose payload the receiver
 * says it would ignore whoever sent it ({@link #setUnverifiedFilter}) is dropped unchecked and
 * counted ({@link #droppedUnverified}): a cell that hears every manager's discovery verifies only
 * those it may answer. A signed datagram whose payload the receiver reads before it is checked
 * ({@link #holdUnverified}: a discovery reply) is held unchecked, and checked (within the budget)
 * when the receiver asks ({@link #checkHeld}).
 *
 * <p>Which vehicle is at which address is learned from authenticated datagrams only (signed, or MAC'd
 * under a session). Same threading as the transport it wraps: one cell thread.
 */
public final class SecureTransport implements AuthenticatingTransport {
    static final int PROBES_PER_RETRY = 16;
    private static final Logger LOG = LoggerFactory.getLogger(SecureTransport.class);

    private final Transport inner;
    private final SecureEndpoint endpoint;
    private final Map<Address, String> peerAt = new HashMap<>();
    private final Map<String, Address> addressOf = new HashMap<>();
    private final SignatureBudget budget = new SignatureBudget(SignatureBudget.PER_SOURCE_PER_SECOND, SignatureBudget.TOTAL_PER_SECOND);
    private AuthenticatedReceiver receiver;
    private UnverifiedTest unverifiedFilter = UnverifiedTest.NONE;
    /** The signed datagrams held unchecked ({@link #holdUnverified}). */
    private final HeldDatagrams held = new HeldDatagrams();
    private long droppedNoReceiver;
    private long droppedUnverified;
    private long droppedOverBudget;
    private long probeIntervalStart = Long.MIN_VALUE;
    private int probesInInterval;

    /** Wraps {@code inner}, whose receiver it takes from now on. */
    public SecureTransport(Transport inner, SecureEndpoint endpoint) {
        this.inner = Objects.requireNonNull(inner, "inner");
        this.endpoint = Objects.requireNonNull(endpoint, "endpoint");
        inner.setReceiver(this::onDatagram);
    }

    @Override
    public Address localAddress() {
        return inner.localAddress();
    }

    /**
     * What the inner transport carries less the largest envelope this layer may put round a
     * datagram (a signature with the credential, or a MAC), so that whatever the layer above sends
     * fits whichever protection it gets.
     */
    @Override
    public int datagramCapacity() {
        int overhead = 0;
        for (Protection p : Protection.values()) {
            overhead = Math.max(overhead, endpoint.overhead(p));
        }
        return Math.min(inner.datagramCapacity(), Transport.MAX_DATAGRAM_BYTES) - overhead;
    }

    /**
     * Sends {@code data} to {@code to}, MAC'd if there is a session with the vehicle there, signed otherwise.
     *
     * @throws PayloadTooLargeException when the protected datagram would not fit
     */
    @Override
    public void send(Address to, byte[] data) {
        String peer = peerAt.get(Objects.requireNonNull(to, "to"));
        if (peer != null && endpoint.hasSession(peer)) {
            inner.send(to, endpoint.wrapFor(peer, data));
            return;
        }
        inner.send(to, endpoint.wrapSigned(data));
        if (peer != null && endpoint.needsHandshake(peer)) {
            inner.send(to, endpoint.startHandshake(peer));
        }
    }

    /** As {@link #send}, but signed when there is no session with the vehicle at {@code to}, and no handshake starts. */
    @Override
    public void sendWithoutHandshake(Address to, byte[] data) {
        String peer = peerAt.get(Objects.requireNonNull(to, "to"));
        inner.send(to, peer != null && endpoint.hasSession(peer) ? endpoint.wrapFor(peer, data) : endpoint.wrapSigned(data));
    }

    /**
     * Broadcasts {@code data} signed, so that anyone who trusts the authority can check it.
     *
     * @throws PayloadTooLargeException when the protected datagram would not fit
     */
    @Override
    public void broadcast(byte[] data) {
        inner.broadcast(endpoint.wrapSigned(data));
    }

    /**
     * Broadcasts {@code data} under the team key: 10 bytes of MAC instead of 64 of signature and a
     * credential, for traffic only team members need.
     *
     * @throws IllegalStateException    when the endpoint holds no team key
     * @throws PayloadTooLargeException when the protected datagram would not fit
     */
    public void teamBroadcast(byte[] data) {
        inner.broadcast(endpoint.wrapTeam(data));
    }

    /**
     * Sends the team key to the vehicle at {@code to}, sealed under the session with it.
     *
     * @throws IllegalStateException when no authenticated vehicle is known there, or there is no session with it or no team key
     */
    public void sendTeamKey(Address to) {
        String peer = peerAt(to).orElseThrow(() -> new IllegalStateException(
                "no authenticated vehicle is known at " + to + " to send the team key to"));
        inner.send(to, endpoint.wrapTeamKey(peer));
    }

    /** The vehicle last authenticated at {@code address}. */
    public Optional<String> peerAt(Address address) {
        return Optional.ofNullable(peerAt.get(address));
    }

    /** Where vehicle {@code peer} last sent an authenticated datagram from. */
    public Optional<Address> addressOf(String peer) {
        return Optional.ofNullable(addressOf.get(peer));
    }

    /** The endpoint underneath, for its counters and sessions. */
    public SecureEndpoint endpoint() {
        return endpoint;
    }

    /** Authenticated payloads that arrived before any receiver was set. */
    public long droppedNoReceiver() {
        return droppedNoReceiver;
    }

    /** Registers the receiver of payloads, which learns only the address they came from. */
    @Override
    public void setReceiver(Receiver receiver) {
        Objects.requireNonNull(receiver, "receiver");
        setAuthenticatedReceiver((sender, from, protection, payload) -> receiver.onDatagram(from, payload));
    }

    @Override
    public Optional<Credential> credentialOf(String peer) {
        return endpoint.credentialOf(peer);
    }

    /**
     * Registers the receiver of payloads, which learns who sent each.
     *
     * @throws IllegalStateException when a receiver is already set
     */
    @Override
    public void setAuthenticatedReceiver(AuthenticatedReceiver receiver) {
        if (this.receiver != null) {
            throw new IllegalStateException("a receiver is already set on the secure transport at " + localAddress());
        }
        this.receiver = Objects.requireNonNull(receiver, "receiver");
    }

    @Override
    public void setUnverifiedFilter(UnverifiedTest ignorable) {
        this.unverifiedFilter = Objects.requireNonNull(ignorable, "ignorable");
    }

    @Override
    public void holdUnverified(UnverifiedTest readable, UnverifiedReceiver receiver) {
        held.set(readable, receiver);
    }

    @Override
    public boolean checkHeld(Address from) {
        return held.check(from, data -> check(from, data));
    }

    /** Signed datagrams held unchecked for the receiver to read first ({@link #holdUnverified}). */
    public long heldUnverified() {
        return held.count();
    }

    /** Signed datagrams dropped unchecked because the receiver would have ignored their payload. */
    public long droppedUnverified() {
        return droppedUnverified;
    }

    @Override
    public void close() {
        inner.close();
    }

    /**
     * Whether {@code datagram} is the traffic of an established session or team ({@code PAIR_MAC},
     * {@code TEAM_MAC}, {@code TEAM_KEY}), checked with a MAC, as opposed to a signed datagram from
     * anyone. Looks at two bytes only: for a transport that hands such traffic to the cell first
     * (say {@code UdpTransport.setUrgent}); the claim is proven later, by the MAC.
     */
    public static boolean isSessionTraffic(byte[] datagram) {
        if (datagram.length < 2 || datagram[0] != FrameCodec.VERSION) {
            return false;
        }
        int kind = datagram[1];
        return kind == FrameCodec.PAIR_MAC || kind == FrameCodec.TEAM_MAC || kind == FrameCodec.TEAM_KEY;
    }

    /** Signed datagrams dropped unchecked because their source (or all sources) spent the signature budget. */
    public long droppedOverBudget() {
        return droppedOverBudget;
    }

    private void onDatagram(Address from, byte[] data) {
        if (!isSessionTraffic(data) && ignorable(data)) {
            droppedUnverified++;
            return;
        }
        byte[] readable = isSessionTraffic(data) ? null : heldPayload(data);
        if (readable != null) {
            held.hold(from, data, readable);
            return;
        }
        check(from, data);
    }

    /** Every check of a datagram that is not dropped unchecked, then its delivery. */
    private void check(Address from, byte[] data) {
        if (!isSessionTraffic(data) && !budget.take(from, endpoint.clock.nowMillis())) {
            droppedOverBudget++;
            LOG.debug("'{}' dropped a signed datagram of {} bytes from {} unchecked: over the signature budget", endpoint.id(), data.length, from);
            return;
        }
        Unwrapped result = endpoint.unwrap(data);
        if (result instanceof Unwrapped.Delivered d) {
            if (d.protection() != Protection.TEAM_MAC) {
                learn(d.sender(), from);
            }
            if (receiver == null) {
                droppedNoReceiver++;
                return;
            }
            receiver.onMessage(d.sender(), from, d.protection(), d.payload());
        } else if (result instanceof Unwrapped.Control c) {
            if (c.event() != Unwrapped.ControlEvent.HANDSHAKE_OFFERED) {
                learn(c.sender(), from);   // an offer may be a replay: it proves nothing about where its sender is now
            }
            c.replyDatagram().ifPresent(reply -> inner.send(from, reply));
        } else if (result instanceof Unwrapped.Rejected r && r.reason() == Rejection.UNKNOWN_SENDER) {
            probe(r.claimedSender(), from);
        }
    }

    /** Whether {@code data} is a signed datagram (not a HELLO) whose payload the receiver would ignore: parsed, not checked. */
    private boolean ignorable(byte[] data) {
        try {
            return FrameCodec.read(data, endpoint.referenceCounter()) instanceof Frame.Signed s
                    && unverifiedFilter.test(s.datagram(), s.payloadStart(), s.signedLength() - s.payloadStart());
        } catch (Malformed m) {
            return false; // refused and counted by the endpoint
        }
    }

    /** The payload of {@code data} when it is a signed datagram (not a HELLO) the receiver reads before it is checked, else null. */
    private byte[] heldPayload(byte[] data) {
        try {
            if (FrameCodec.read(data, endpoint.referenceCounter()) instanceof Frame.Signed s) {
                return held.accepts(s.datagram(), s.payloadStart(), s.signedLength() - s.payloadStart())
                        ? Arrays.copyOfRange(s.datagram(), s.payloadStart(), s.signedLength()) : null;
            }
            return null;
        } catch (Malformed m) {
            return null; // refused and counted by the endpoint
        }
    }

    /** A peer MACs under a session this side does not have: offer a new one, within the probe budget. */
    private void probe(String claimed, Address from) {
        if (claimed == null || claimed.equals(endpoint.id()) || !endpoint.needsHandshake(claimed)) {
            return;
        }
        long now = endpoint.clock.nowMillis();
        if (probeIntervalStart == Long.MIN_VALUE || now - probeIntervalStart >= endpoint.settings.handshakeRetryMillis()) {
            probeIntervalStart = now;
            probesInInterval = 0;
        }
        if (probesInInterval < PROBES_PER_RETRY) {
            probesInInterval++;
            LOG.debug("'{}' offers a handshake to '{}' at {}, which MACs under a session it does not have", endpoint.id(), claimed, from);
            inner.send(from, endpoint.startHandshake(claimed));
        }
    }

    private void learn(String peer, Address from) {
        Address before = addressOf.put(peer, from);
        if (before != null && !before.equals(from)) {
            peerAt.remove(before, peer);
        }
        peerAt.put(from, peer);
    }
}
