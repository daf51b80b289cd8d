package net.smc.core.router;

import net.smc.core.message.Envelope;
import net.smc.core.message.MessageType;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The Message-Router of the paper (section IV-A): hands each incoming packet to the roles (and
 * other {@link Subscriber}s) of the cell that registered for it, by type, by source, or by both.
 *
 * <h2>What a subscriber receives</h2>
 * A registration selects a set of (type, source) pairs: all pairs of one type, all pairs of one
 * source, or one pair. Registrations and de-registrations of one subscriber compose in order, as
 * set union and set difference: after any sequence, a subscriber receives a packet of type T from
 * source S exactly when the last of its operations whose pattern covers (T, S) was a
 * registration. So a role registered for type T and for source S receives a T from S once
 * (its registrations are aggregated); a role registered for all of T that de-registers T from S
 * stops receiving T from S only; and a role that registers again receives again. Each subscriber
 * receives each packet at most once.
 *
 * <h2>The tables</h2>
 * Each subscriber has a slot, one bit in every table entry (see {@link CopyOnWriteBits}).
 * <ul>
 *   <li>The dispatch table: by type, an array indexed by {@link MessageType#ordinal()} of the
 *       subscribers registered for that whole type; by source, a hash map to a {@link SourceRow}
 *       with the subscribers registered for the whole source and, per type, those registered for
 *       that type from that source.</li>
 *   <li>The exclusion table: per source and type, the subscribers that de-registered that pair
 *       while one of their aggregate registrations (the whole type, or the whole source) still
 *       covers it. It lives in the same {@code SourceRow}, so one lookup finds both.</li>
 * </ul>
 * Dispatch checks both: the receivers are {@code (type | source | pair) & ~excluded}, a few word
 * operations after one map lookup, whatever the number of registrations; an OR of bit sets is what
 * makes overlapping registrations of one subscriber count once. {@link RoutingTables} keeps the
 * tables canonical, so they stay as small as the registrations.
 *
 * <p>Dispatch delivers in slot order (the order in which subscribers first registered, slots of
 * removed subscribers being reused), so a run is deterministic. The receivers of a packet are
 * fixed when its dispatch starts: a subscriber may register, de-register or dispatch from
 * {@link Subscriber#receive}, and the change applies from the next packet. Not thread-safe: a
 * cell's router is used on the cell's thread.
 */
public final class MessageRouter {
    private static final Logger log = LoggerFactory.getLogger(MessageRouter.class);

    private final RoutingTables tables = new RoutingTables();
    private long dispatched;
    private long deliveries;
    private long unrouted;
    private long failures;

    /** Registers {@code subscriber} for every packet of {@code type}, from any source. */
    public void register(Subscriber subscriber, MessageType type) {
        tables.addType(check(subscriber), check(type).ordinal());
    }

    /** Registers {@code subscriber} for every packet from {@code source}, of any type. */
    public void register(Subscriber subscriber, String source) {
        tables.addSource(check(subscriber), check(source));
    }

    /** Registers {@code subscriber} for packets of {@code type} from {@code source}. */
    public void register(Subscriber subscriber, MessageType type, String source) {
        tables.addPair(check(subscriber), check(type).ordinal(), check(source));
    }

    /** De-registers {@code subscriber} from every packet of {@code type}, whatever registration selected it. */
    public void deregister(Subscriber subscriber, MessageType type) {
        tables.removeType(check(subscriber), check(type).ordinal());
    }

    /** De-registers {@code subscriber} from every packet from {@code source}, whatever registration selected it. */
    public void deregister(Subscriber subscriber, String source) {
        tables.removeSource(check(subscriber), check(source));
    }

    /**
     * De-registers {@code subscriber} from packets of {@code type} from {@code source}; inside an
     * aggregate registration this adds an entry to the exclusion table.
     */
    public void deregister(Subscriber subscriber, MessageType type, String source) {
        tables.removePair(check(subscriber), check(type).ordinal(), check(source));
    }

    /** Removes every registration and exclusion of {@code subscriber} (a withdrawn role), and frees its slot. */
    public void deregisterAll(Subscriber subscriber) {
        tables.removeAll(check(subscriber));
    }

    /** Whether a packet of {@code type} from {@code source} would reach {@code subscriber}. */
    public boolean receives(Subscriber subscriber, MessageType type, String source) {
        return tables.receives(check(subscriber), check(type).ordinal(), check(source));
    }

    /**
     * Hands {@code envelope} to every subscriber whose registrations select it, each once, in slot
     * order. A packet nobody selects is counted as unrouted (and logged at debug level).
     *
     * @return how many subscribers received it
     */
    public int dispatch(Envelope envelope) {
        int t = envelope.body().type().ordinal();
        // Read every array once: they are copy-on-write, so changes made by receivers cannot reach them.
        Subscriber[] receivers = tables.slots.snapshot();
        long[] type = tables.byType[t];
        SourceRow row = tables.bySource.get(envelope.sender());
        long[] all = CopyOnWriteBits.EMPTY;
        long[] pair = CopyOnWriteBits.EMPTY;
        long[] excluded = CopyOnWriteBits.EMPTY;
        if (row != null) {
            all = row.all;
            pair = row.pairs[t];
            excluded = row.excluded[t];
        }
        dispatched++;
        int n = 0;
        int words = receivers.length + 63 >>> 6;
        for (int w = 0; w < words; w++) {
            long bits = (CopyOnWriteBits.word(type, w) | CopyOnWriteBits.word(all, w) | CopyOnWriteBits.word(pair, w)) & ~CopyOnWriteBits.word(excluded, w);
            while (bits != 0) {
                deliver(receivers[w << 6 | Long.numberOfTrailingZeros(bits)], envelope);
                bits &= bits - 1;
                n++;
            }
        }
        deliveries += n;
        if (n == 0) {
            unrouted++;
            if (log.isDebugEnabled()) {
                log.debug("no subscriber for {} from '{}' (id {})", envelope.type(), envelope.sender(), envelope.id());
            }
        }
        return n;
    }

    private void deliver(Subscriber subscriber, Envelope envelope) {
        try {
            subscriber.receive(envelope);
        } catch (RuntimeException e) {
            failures++;
            log.warn("subscriber {} failed on {} from '{}' (id {})", subscriber, envelope.type(), envelope.sender(),
                    envelope.id(), e);
        }
    }

    /** Packets dispatched. */
    public long dispatched() {
        return dispatched;
    }

    /** Packets handed to subscribers (a packet counts once per receiver). */
    public long deliveries() {
        return deliveries;
    }

    /** Packets no subscriber selected. */
    public long unrouted() {
        return unrouted;
    }

    /** Deliveries whose subscriber threw. */
    public long failures() {
        return failures;
    }

    /** Subscribers with a slot. */
    public int subscribers() {
        return tables.slots.size();
    }

    /** Sources with a row (for tests: rows must not outlive their registrations). */
    int sourceRows() {
        return tables.bySource.size();
    }

    private static Subscriber check(Subscriber s) {
        if (s == null) {
            throw new IllegalArgumentException("subscriber is null; a registration needs a subscriber");
        }
        return s;
    }

    private static MessageType check(MessageType t) {
        if (t == null) {
            throw new IllegalArgumentException("type is null; a registration by type needs a message type");
        }
        return t;
    }

    private static String check(String source) {
        if (source == null || source.isEmpty()) {
            throw new IllegalArgumentException("source is " + (source == null ? "null" : "empty")
                    + "; a registration by source needs a vehicle id");
        }
        return source;
    }
}
