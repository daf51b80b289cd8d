package net.smc.core.comm;

import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.LongSupplier;
import java.util.random.RandomGenerator;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import net.smc.core.message.Ack;
import net.smc.core.message.Acks;
import net.smc.core.message.Envelope;
import net.smc.core.message.Message;
import net.smc.core.message.WireFormat;
import net.smc.core.transport.Address;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Scheduler;

/**
 * The Message-Sender of the paper (section IV-A): reliable delivery of critical messages (role
 * assignments, capability descriptions, ...) over connectionless datagrams. See
 * <a href="doc-files/reliable-delivery.md">the reliable-delivery design note</a>.
 *
 * <p>As sender, it gives each message an id, transmits it and waits for an {@link Ack} (or an
 * {@link Acks} among whose ids it is) naming that id from the address it went to; without one, it retransmits with exponential backoff and
 * jitter ({@link SenderSettings}) and after the last try tells the {@link DeliveryListener} that
 * delivery failed. As receiver, it acknowledges every critical copy that arrives (a lost Ack must
 * be replaced; the acknowledgements of one burst go to each peer coalesced in one datagram) but lets each {@code (sender, id)} through only once, so the application sees each
 * message exactly once however often the network or a retransmission repeats it.
 *
 * <p>Sans-IO and single-threaded: it uses only the clock, scheduler and transport of its cell,
 * and every method must be called on the cell's thread. The {@link CommunicationManager} makes one
 * per cell and feeds it; applications reach it through the manager.
 */
public final class MessageSender {
    private static final Logger log = LoggerFactory.getLogger(MessageSender.class);
    /** The least reordering window of {@link #suspectLost}, ms. */
    static final long MIN_REORDER_MILLIS = 2;
    /** A tail probe waits this many of the peer's smoothed round trips ({@link #armProbe}). */
    static final double PROBE_ROUND_TRIPS = 2.0;
    /** ... and at least this long, ms. */
    static final long MIN_PROBE_MILLIS = 4;

    private final String self;
    private final Clock clock;
    private final Wire wire;
    private final IdSource ids;
    private final SenderSettings settings;
    private final Backoff backoff;
    /** The round-trip estimates that set each first timeout; null when the settings fix it. */
    private final RttEstimator rtt;
    /** How long the transport's queue holds what is handed to it now, in ms. */
    private final LongSupplier backlog;
    private final PendingTable pending = new PendingTable();
    /** Messages lost before their timeout, told by the Acks of later ones; null when the timeout is fixed. */
    private final LossDetector losses;
    private final RetryTimer timer;
    /**
     * Per peer, the critical message transmitted to it last, while it is outstanding: the one a tail
     * probe would send again ({@link #armProbe}). Empty when the timeout is fixed.
     */
    private final Map<Address, Pending> lastTransmitted = new HashMap<>();
    private final DuplicateWindow window;
    private final SenderCounters counters = new SenderCounters();
    private final Scheduler scheduler;
    private final Map<Address, AckBatch> waitingAcks = new LinkedHashMap<>();
    private boolean flushScheduled;
    private boolean stopped;

    MessageSender(String self, Clock clock, Scheduler scheduler, RandomGenerator random, SenderSettings settings,
                  Wire wire, IdSource ids) {
        this.backlog = wire::backlogMillis;
        this.rtt = settings.adaptive() ? new RttEstimator(settings) : null;
        this.losses = settings.adaptive() ? new LossDetector() : null;
        this.self = self;
        this.clock = clock;
        this.wire = wire;
        this.ids = ids;
        this.scheduler = scheduler;
        this.settings = settings;
        this.backoff = new Backoff(settings, random);
        this.timer = new RetryTimer(clock, scheduler, this::timedOut);
        this.window = new DuplicateWindow(settings.duplicateWindowMillis(), settings.duplicateWindowEntries());
    }

    /**
     * Sends {@code message} to {@code to} reliably; {@code listener} learns the outcome later, on
     * the cell's thread.
     *
     * @return the message's id, which the listener's calls and the peer's Ack name
     * @throws IllegalStateException when the sender was stopped
     */
    public long send(Address to, Message message, DeliveryListener listener) {
        if (stopped) {
            throw new IllegalStateException("message sender of '" + self + "' is stopped; cannot send "
                    + message.type() + " to " + to);
        }
        long id = ids.next();
        List<byte[]> datagrams = wire.encode(new Envelope(self, id, message));
        Pending p = new Pending(id, to, message.type(), datagrams, listener, clock.nowMillis(), firstTimeoutMillis(to));
        transmit(p); // first, so that a transport that refuses leaves nothing behind
        pending.add(p);
        if (losses != null) {
            losses.sent(p);
        }
        counters.sent++;
        return id;
    }

    /** Handles an Ack that arrived from {@code from}: settles the message it names, if still outstanding. */
    void acknowledged(Address from, Ack ack) {
        settle(from, ack.acked());
    }

    /** Handles an Acks that arrived from {@code from}: settles each id in turn, exactly as an Ack would. */
    void acknowledged(Address from, Acks acks) {
        List<Long> acked = acks.acked();
        for (int i = 0; i < acked.size(); i++) {
            settle(from, acked.get(i));
        }
    }

    private void settle(Address from, long id) {
        Pending p = pending.get(id);
        if (p == null) {
            counters.unknownAcks++;
            return;
        }
        if (!p.to.equals(from)) {
            counters.misdirectedAcks++;
            log.debug("'{}': Ack for {} came from {}, not from its destination; ignored", self, p, from);
            return;
        }
        pending.remove(p.id);
        p.settled = true;
        counters.acked++;
        if (rtt != null && p.tries == 1 && !p.probed) { // Karn's rule: the Ack of a message sent again may answer any copy
            rtt.sample(p.to, Math.max(0, clock.nowMillis() - p.firstDepartureMillis));
            losses.acked(p, this::suspectLost);
        } else if (losses != null && p.probed) {
            losses.ackedAgain(p, this::suspectLost);
        } else if (losses != null) {
            losses.settled(p);
        }
        if (rtt != null && !lastTransmitted.remove(p.to, p)) {
            probeAfterAck(p.to);
        }
        try {
            p.listener.delivered(p.id);
        } catch (RuntimeException e) {
            log.warn("'{}': delivery listener failed on delivered({}) for {}", self, p.id, p, e);
        }
    }

    /**
     * Checks a critical message that arrived against the duplicate window.
     *
     * @return true the first time this {@code (sender, id)} arrives within the window: the
     *         application should have it; false for a duplicate, which is counted
     */
    boolean admit(Envelope envelope) {
        if (window.firstSeen(envelope.sender(), envelope.id(), clock.nowMillis())) {
            counters.delivered++;
            return true;
        }
        counters.duplicates++;
        return false;
    }

    /**
     * Acknowledges a critical message to the address it came from, every time it arrives: if an
     * earlier Ack was lost, this one settles the sender. Called after the message was handed to
     * the application, so that "delivered" at the sender means the application had it.
     *
     * <p>The acknowledgement is coalesced: the id waits with the others for the same address until
     * a flush task, scheduled with delay 0 when the first id starts waiting, runs after the current
     * burst of incoming datagrams; then each address gets one datagram, an {@link Ack} for a single
     * id, an {@link Acks} for several. An address with {@link WireFormat#MAX_ACKS} ids waiting is
     * flushed at once.
     */
    void acknowledge(Address from, Envelope envelope) {
        if (stopped) {
            return;
        }
        counters.acksSent++;
        AckBatch batch = waitingAcks.get(from);
        if (batch == null) {
            batch = new AckBatch();
            waitingAcks.put(from, batch);
        }
        batch.ids[batch.size++] = envelope.id();
        if (batch.size == WireFormat.MAX_ACKS) {
            waitingAcks.remove(from);
            sendAcks(from, batch);
        }
        if (!flushScheduled && !waitingAcks.isEmpty()) {
            flushScheduled = true;
            scheduler.schedule(0, this::flushAcks);
        }
    }

    /** The flush task: one datagram to each address with acknowledgements waiting, in arrival order. */
    private void flushAcks() {
        flushScheduled = false;
        if (stopped) {
            waitingAcks.clear();
            return;
        }
        for (Map.Entry<Address, AckBatch> e : waitingAcks.entrySet()) {
            sendAcks(e.getKey(), e.getValue());
        }
        waitingAcks.clear();
    }

    private void sendAcks(Address to, AckBatch batch) {
        Message body;
        if (batch.size == 1) {
            body = new Ack(batch.ids[0]);
        } else {
            Long[] acked = new Long[batch.size];
            for (int i = 0; i < batch.size; i++) {
                acked[i] = batch.ids[i];
            }
            body = new Acks(Arrays.asList(acked));
        }
        wire.send(to, wire.encode(new Envelope(self, ids.next(), body)));
        counters.ackDatagrams++;
    }

    /** Ids acknowledged to one address and not yet sent. */
    private static final class AckBatch {
        final long[] ids = new long[WireFormat.MAX_ACKS];
        int size;
    }

    /**
     * Stops retransmitting and reports every outstanding message failed ({@link FailureReason#STOPPED}),
     * in send order. Later sends throw; stopping again does nothing.
     */
    public void stop() {
        if (stopped) {
            return;
        }
        stopped = true;
        timer.stop();
        lastTransmitted.clear();
        if (losses != null) {
            losses.clear();
        }
        for (Pending p : pending.drain()) {
            fail(p, FailureReason.STOPPED);
        }
    }

    /** Critical messages sent and neither acknowledged nor failed yet. */
    public int outstanding() {
        return pending.size();
    }

    public SenderCounters counters() {
        return counters;
    }

    public SenderSettings settings() {
        return settings;
    }

    /** Messages remembered by the duplicate window now. */
    int remembered() {
        return window.size();
    }

    /** Entries the duplicate window forgot before their time because it was full. */
    public long duplicateWindowEvictions() {
        return window.evictedEarly();
    }

    /**
     * A round trip to {@code peer} measured outside this sender: a reply that names the request it
     * answers (a discovery reply names its discovery), from when the request left this cell's
     * transport to when the reply arrived. It counts as the Ack of a message sent once would, so a
     * peer is measured before the first critical message to it. Nothing when the timeout is fixed.
     *
     * @throws IllegalArgumentException when it is negative
     */
    public void roundTrip(Address peer, long rttMillis) {
        if (rtt != null) {
            rtt.sample(peer, rttMillis);
        }
    }

    /**
     * The first-try timeout a message to {@code peer} would get now: its round-trip estimate, the
     * cell's when it has none, the initial timeout when nothing was measured or the timeout is fixed.
     */
    public long firstTimeoutMillis(Address peer) {
        return rtt == null ? settings.initialTimeoutMillis() : rtt.timeoutMillis(peer);
    }

    /**
     * The cell's retransmission timeout over all its peers ({@link #firstTimeoutMillis} of a peer
     * never measured): how long the answers to a request broadcast to many may take.
     */
    public long cellTimeoutMillis() {
        return rtt == null ? settings.initialTimeoutMillis() : rtt.cellTimeoutMillis();
    }

    /** The loss detector, null when the first timeout is fixed (for tests). */
    LossDetector losses() {
        return losses;
    }

    /** The round-trip estimates, null when the first timeout is fixed (for tests). */
    RttEstimator rtt() {
        return rtt;
    }

    /**
     * Sends a copy and sets its deadline. With a fixed timeout, from now; with an adaptive one, from
     * when the copy leaves the transport (a message behind a queue of others is not retransmitted
     * before it is out), backing off from the message's first timeout, but never later than the fixed
     * schedule would from now; the last try waits until the fixed schedule's give-up time.
     */
    private void transmit(Pending p) {
        p.tries++;
        wire.send(p.to, p.datagrams);
        long now = clock.nowMillis();
        if (rtt == null) {
            p.deadlineMillis = now + backoff.timeoutMillis(p.tries);
        } else {
            long queued = backlog.getAsLong();
            p.departureMillis = now + queued;
            if (p.tries == 1) {
                p.firstDepartureMillis = p.departureMillis;
            }
            long deadline = now + backoff.timeoutMillis(p.tries, p.firstTimeoutMillis, queued);
            if (p.tries == settings.maxTries()) {
                deadline = Math.max(deadline, backoff.giveUpMillis(p.firstSentMillis));
            }
            p.deadlineMillis = deadline;
            armProbe(p, now, queued);
        }
        timer.watch(p);
    }

    /**
     * The tail probe (the idea of RFC 8985's tail loss probe, on messages): {@code p} was just
     * transmitted to its peer, so it is the last message of the flight to that peer. If a later one
     * follows, the loss detector finds a loss of {@code p} from that one's Ack; if none does, a lost
     * {@code p} would wait for its timeout (at least 50 ms, more while the peer was never measured,
     * backing off after a retransmission). So unless {@code p} is acknowledged, or another message
     * goes to the peer, within twice the peer's smoothed round trip from when the copy leaves the
     * transport, {@code p} is sent again then, once. The probe is an extra copy: the message's tries,
     * timeout and give-up time stand (a probe into a link that is down costs one datagram, not a
     * backed-off try), its Ack is no round-trip sample (it may answer either copy), and the Ack both
     * settles {@code p} and lets the loss detector find the messages lost before it. Not armed when
     * the timeout comes first; for a peer not measured yet, armed by its first Ack ({@link #probeAfterAck}).
     */
    private void armProbe(Pending p, long now, long queued) {
        lastTransmitted.put(p.to, p);
        p.probeAtMillis = 0;
        double srtt = rtt.smoothedRttMillis(p.to);
        if (!Double.isNaN(srtt)) {
            scheduleProbe(p, now, now + queued + probeWaitMillis(srtt));
        }
    }

    /**
     * An Ack came from {@code peer}: the message last transmitted to it, if still outstanding, is probed
     * two round trips after its copy left the transport (or from now, if it has), if that is sooner
     * than its probe was due (the peer may have been measured only now).
     */
    private void probeAfterAck(Address peer) {
        Pending last = lastTransmitted.get(peer);
        double srtt = rtt.smoothedRttMillis(peer);
        if (last != null && !last.settled && !Double.isNaN(srtt)) {
            long now = clock.nowMillis();
            scheduleProbe(last, now, Math.max(now, last.departureMillis) + probeWaitMillis(srtt));
        }
    }

    private static long probeWaitMillis(double srtt) {
        return Math.max(MIN_PROBE_MILLIS, (long) Math.ceil(PROBE_ROUND_TRIPS * srtt));
    }

    private void scheduleProbe(Pending p, long now, long at) {
        if (p.probed || at >= p.deadlineMillis || (p.probeAtMillis != 0 && p.probeAtMillis <= at)) {
            return;
        }
        p.probeAtMillis = at;
        int tries = p.tries;
        scheduler.schedule(at - now, () -> {
            if (stopped || p.settled || p.tries != tries || p.probeAtMillis != at || lastTransmitted.get(p.to) != p) {
                return;
            }
            p.probed = true;
            counters.probes++;
            try {
                wire.send(p.to, p.datagrams);
            } catch (RuntimeException e) {
                log.debug("'{}': tail probe of {} refused by the transport; its timeout stands", self, p, e);
            }
        });
    }

    /**
     * A message sent to the same peer after {@code p} was acknowledged while {@code p} was not: unless
     * its Ack comes within the reordering window (a quarter of the peer's smoothed round trip, as
     * RFC 8985's first window, and at least {@link #MIN_REORDER_MILLIS}: copies sent close together
     * may pass each other on the way), it is sent again then rather than at its timeout, as its second
     * try: the backoff and the give-up time go on from there, and its Ack is no round-trip sample.
     * On the set-up experiment's radio (up to 4 ms of jitter each way) a quarter recovered the most:
     * half a round trip or a whole one waited longer for copies that were lost.
     */
    private void suspectLost(Pending p) {
        double srtt = rtt.smoothedRttMillis(p.to);
        long window = Math.max(MIN_REORDER_MILLIS, Double.isNaN(srtt) ? 0 : (long) Math.ceil(srtt / 4));
        scheduler.schedule(window, () -> {
            if (stopped || p.settled || p.tries != 1) {
                return;
            }
            counters.fastRetransmitted++;
            retransmit(p);
        });
    }

    private void timedOut(Pending p) {
        if (rtt != null && p.tries == 1) {
            rtt.timedOut(p.to);
        }
        if (p.tries >= settings.maxTries()) {
            pending.remove(p.id);
            fail(p, FailureReason.NO_ACK);
            return;
        }
        retransmit(p);
    }

    /** Sends {@code p} again; a transport that refuses fails it ({@link FailureReason#SEND_ERROR}). */
    private void retransmit(Pending p) {
        counters.retransmitted++;
        try {
            transmit(p);
        } catch (RuntimeException e) {
            log.warn("'{}': retransmission of {} refused by the transport", self, p, e);
            pending.remove(p.id);
            fail(p, FailureReason.SEND_ERROR);
        }
    }

    private void fail(Pending p, FailureReason reason) {
        p.settled = true;
        lastTransmitted.remove(p.to, p);
        if (losses != null) {
            losses.settled(p);
        }
        counters.failed++;
        log.debug("'{}': gave up on {} after {} ms: {}", self, p, clock.nowMillis() - p.firstSentMillis, reason);
        try {
            p.listener.failed(p.id, reason);
        } catch (RuntimeException e) {
            log.warn("'{}': delivery listener failed on failed({}, {}) for {}", self, p.id, reason, p, e);
        }
    }
}
