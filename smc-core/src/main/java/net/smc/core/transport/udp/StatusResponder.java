package net.smc.core.transport.udp;

import net.smc.core.transport.Transport;
import net.smc.core.transport.udp.StatusClient;
import net.smc.core.transport.Receiver;
import net.smc.core.transport.ForwardingTransport;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Address;
import static java.nio.charset.StandardCharsets.US_ASCII;
import static java.nio.charset.StandardCharsets.UTF_8;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.function.Supplier;

import net.smc.core.transport.real.SystemClock;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A {@link Transport} that answers status queries itself and passes every other datagram on, so a
 * running cell can be asked "what is your view?" from outside ({@code smc status}, {@link StatusClient})
 * without the cell's protocols knowing about it.
 *
 * <p>The exchange, one datagram each way:
 * <ul>
 *   <li>query: exactly {@link #QUERY_MAGIC} ({@code "SMC?STAT"}) followed by the version byte
 *       {@value #VERSION}, nothing else;</li>
 *   <li>reply, sent to the query's {@code from} address: {@link #REPLY_MAGIC} ({@code "SMC!STAT"}), the
 *       version byte, then the cell's view as UTF-8 JSON, from the supplier given at construction.
 *       When the view does not fit in one datagram ({@link #MAX_JSON_BYTES}), the reply carries
 *       {@code {"error":"status view too large","bytes":N,"limit":L}} instead.</li>
 * </ul>
 * A datagram that starts with the 8-byte query magic but is not a valid query (another version,
 * bytes after the version) is dropped and counted as {@linkplain #malformed() malformed}; it is
 * never a cell message, whose first three bytes are {@code "SM"} and version 1. Every other
 * datagram, including one shorter than the magic, goes unchanged to the receiver registered with
 * {@link #setReceiver}. Replies are limited to {@value #DEFAULT_REPLIES_PER_SECOND} in any second by
 * default, so a flood of queries cannot turn a cell into a traffic amplifier or keep its thread
 * busy rendering views; queries over the limit are dropped and counted as {@linkplain #refused() refused}.
 *
 * <p><b>Security:</b> the query is read-only and unauthenticated. Anyone who can send a datagram to
 * the cell's unicast address gets the JSON view, and nothing else: a query changes no state and
 * cannot reach the cell's protocols. Put this decorator directly on the network transport, under
 * any authenticating layer ({@code SecureTransport(new StatusResponder(udp, view), ...)}), so that
 * queries never meet the authentication, and put nothing in the view that must stay secret.
 *
 * <p>Threading: that of the wrapped transport. The receiver (and so the view supplier) runs on the
 * cell's thread; the counters are written there and may be read from any thread.
 */
public final class StatusResponder extends ForwardingTransport {
    private static final Logger LOG = LoggerFactory.getLogger(StatusResponder.class);
    private static final ObjectMapper JSON = new ObjectMapper();

    /** The first 8 bytes of a status query: ASCII {@code SMC?STAT}. */
    public static final byte[] QUERY_MAGIC = "SMC?STAT".getBytes(US_ASCII);
    /** The first 8 bytes of a status reply: ASCII {@code SMC!STAT}. */
    public static final byte[] REPLY_MAGIC = "SMC!STAT".getBytes(US_ASCII);
    /** The version byte after either magic. */
    public static final byte VERSION = 1;
    /** Magic plus version: the whole of a query, and the bytes before a reply's JSON. */
    public static final int HEADER_BYTES = 9;
    /** The most bytes of JSON one reply can carry. */
    public static final int MAX_JSON_BYTES = MAX_DATAGRAM_BYTES - HEADER_BYTES;
    /** Replies allowed in any 1,000 ms, unless the constructor says otherwise. */
    public static final int DEFAULT_REPLIES_PER_SECOND = 20;
    /** Replies one source address may get in any 1,000 ms, unless the constructor says otherwise. */
    public static final int DEFAULT_REPLIES_PER_SOURCE = 4;
    private static final int MAX_SOURCES = 1024;

    private static final long WINDOW_MILLIS = 1_000;

    private final Supplier<String> view;
    private final Clock clock;
    /** When each of the last replies went out, oldest at {@link #next}; {@code Long.MIN_VALUE} for none. */
    private final long[] replyTimes;
    private int next;
    private final int perSource;
    /** Per source address, when its last replies went out (a ring of {@link #perSource}). */
    private final Map<Address, long[]> sourceTimes = new java.util.HashMap<>();
    private Receiver receiver;
    private volatile long answered;
    private volatile long refused;
    private volatile long malformed;
    private volatile long passedOn;
    private volatile long droppedNoReceiver;

    /**
     * Wraps {@code inner}, whose receiver it takes from now on, with the real clock and
     * {@value #DEFAULT_REPLIES_PER_SECOND} replies per second.
     *
     * @param view the cell's view as JSON, asked for once per answered query on the cell's thread
     */
    public StatusResponder(Transport inner, Supplier<String> view) {
        this(inner, view, new SystemClock(), DEFAULT_REPLIES_PER_SECOND, DEFAULT_REPLIES_PER_SOURCE);
    }

    /**
     * Wraps {@code inner}, whose receiver it takes from now on.
     *
     * @param view              the cell's view as JSON, asked for once per answered query on the cell's thread
     * @param clock             the time the rate limit is measured in
     * @param repliesPerSecond  replies allowed in any 1,000 ms, at least 1
     */
    public StatusResponder(Transport inner, Supplier<String> view, Clock clock, int repliesPerSecond) {
        this(inner, view, clock, repliesPerSecond, repliesPerSecond);
    }

    /**
     * Wraps {@code inner}, whose receiver it takes from now on.
     *
     * @param view              the cell's view as JSON, asked for once per answered query on the cell's thread
     * @param clock             the time the rate limits are measured in
     * @param repliesPerSecond  replies allowed in any 1,000 ms in all, at least 1
     * @param perSource         replies one source address may get in any 1,000 ms, 1 to {@code repliesPerSecond}:
     *                          one flooding source cannot take every reply
     */
    public StatusResponder(Transport inner, Supplier<String> view, Clock clock, int repliesPerSecond, int perSource) {
        super(inner);
        if (repliesPerSecond < 1) {
            throw new IllegalArgumentException("repliesPerSecond is " + repliesPerSecond + "; it must be 1 or more");
        }
        if (perSource < 1 || perSource > repliesPerSecond) {
            throw new IllegalArgumentException("perSource is " + perSource + "; it must be 1 to repliesPerSecond (" + repliesPerSecond + ")");
        }
        this.perSource = perSource;
        this.view = Objects.requireNonNull(view, "view");
        this.clock = Objects.requireNonNull(clock, "clock");
        if (repliesPerSecond < 1) {
            throw new IllegalArgumentException("repliesPerSecond is " + repliesPerSecond + "; it must be 1 or more");
        }
        this.replyTimes = new long[repliesPerSecond];
        Arrays.fill(replyTimes, Long.MIN_VALUE);
        inner.setReceiver(this::onDatagram);
    }

    /** Whether {@code datagram} starts as a status query does: for a transport that hands queries to the cell first. */
    public static boolean looksLikeQuery(byte[] datagram) {
        return startsWith(datagram, datagram.length, QUERY_MAGIC);
    }

    /** The query datagram a client sends: magic and version. */
    public static byte[] query() {
        byte[] query = Arrays.copyOf(QUERY_MAGIC, HEADER_BYTES);
        query[QUERY_MAGIC.length] = VERSION;
        return query;
    }

    /**
     * The JSON a reply carries, or null when {@code datagram} is not a reply of this version.
     */
    public static String replyJson(byte[] datagram, int length) {
        if (length < HEADER_BYTES || !startsWith(datagram, length, REPLY_MAGIC) || datagram[REPLY_MAGIC.length] != VERSION) {
            return null;
        }
        return new String(datagram, HEADER_BYTES, length - HEADER_BYTES, UTF_8);
    }

    @Override
    public void setReceiver(Receiver receiver) {
        Objects.requireNonNull(receiver, "receiver");
        if (this.receiver != null) {
            throw new IllegalStateException("transport " + localAddress() + " already has a receiver; it takes one");
        }
        this.receiver = receiver;
    }

    /** Queries answered with a reply (the view, or the too-large error). */
    public long answered() {
        return answered;
    }

    /** Valid queries dropped because the rate limit was reached. */
    public long refused() {
        return refused;
    }

    /** Datagrams that started with the query magic but were not a valid query; dropped. */
    public long malformed() {
        return malformed;
    }

    /** Datagrams handed on to the receiver. */
    public long passedOn() {
        return passedOn;
    }

    /** Datagrams to pass on that arrived before any receiver was set; dropped. */
    public long droppedNoReceiver() {
        return droppedNoReceiver;
    }

    private void onDatagram(Address from, byte[] data) {
        if (!startsWith(data, data.length, QUERY_MAGIC)) {
            passOn(from, data);
        } else if (data.length != HEADER_BYTES || data[QUERY_MAGIC.length] != VERSION) {
            malformed++;
            LOG.debug("status query from {} refused as malformed: {} bytes, version byte {}", from, data.length,
                    data.length > QUERY_MAGIC.length ? data[QUERY_MAGIC.length] : "missing");
        } else if (!takeReplySlot(from)) {
            refused++;
        } else {
            answered++;   // before the send, so whoever gets the reply sees it counted
            inner.send(from, reply());
        }
    }

    private void passOn(Address from, byte[] data) {
        if (receiver == null) {
            droppedNoReceiver++;
            return;
        }
        passedOn++;
        receiver.onDatagram(from, data);
    }

    /**
     * Whether a reply may go now to {@code from}: fewer than the limit went out in the last second,
     * and fewer than the per-source limit to {@code from}. Takes both slots if so.
     */
    private boolean takeReplySlot(Address from) {
        long now = clock.nowMillis();
        long oldest = replyTimes[next];
        if (oldest != Long.MIN_VALUE && now - oldest < WINDOW_MILLIS) {
            return false;
        }
        long[] mine = sourceTimes.get(from);
        if (mine == null) {
            if (sourceTimes.size() >= MAX_SOURCES) {
                sourceTimes.values().removeIf(t -> Arrays.stream(t).allMatch(x -> x == Long.MIN_VALUE || now - x >= WINDOW_MILLIS));
            }
            mine = new long[perSource + 1];   // the last slot is the ring's next index
            Arrays.fill(mine, 0, perSource, Long.MIN_VALUE);
            sourceTimes.put(from, mine);
        }
        int at = (int) mine[perSource];
        if (mine[at] != Long.MIN_VALUE && now - mine[at] < WINDOW_MILLIS) {
            return false;   // this source had its share of the last second
        }
        mine[at] = now;
        mine[perSource] = (at + 1) % perSource;
        replyTimes[next] = now;
        next = (next + 1) % replyTimes.length;
        return true;
    }

    private byte[] reply() {
        byte[] json = viewBytes();
        if (json.length > MAX_JSON_BYTES) {
            json = errorObject("status view too large", "bytes", json.length, "limit", MAX_JSON_BYTES);
        }
        byte[] reply = Arrays.copyOf(REPLY_MAGIC, HEADER_BYTES + json.length);
        reply[REPLY_MAGIC.length] = VERSION;
        System.arraycopy(json, 0, reply, HEADER_BYTES, json.length);
        return reply;
    }

    /** The view as UTF-8; a view that fails becomes an error object, so the asker learns why. */
    private byte[] viewBytes() {
        try {
            return Objects.requireNonNull(view.get(), "the status view supplier returned null").getBytes(UTF_8);
        } catch (RuntimeException e) {
            LOG.warn("status view of {} failed", localAddress(), e);
            return errorObject("status view failed", "exception", e.getClass().getName());
        }
    }

    /** {@code {"error": what, name1: value1, ...}} as UTF-8 JSON. */
    private static byte[] errorObject(String what, Object... namesAndValues) {
        Map<String, Object> fields = new LinkedHashMap<>();
        fields.put("error", what);
        for (int i = 0; i < namesAndValues.length; i += 2) {
            fields.put((String) namesAndValues[i], namesAndValues[i + 1]);
        }
        try {
            return JSON.writeValueAsBytes(fields);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("cannot write a status error object: " + e.getMessage(), e);
        }
    }

    private static boolean startsWith(byte[] data, int length, byte[] prefix) {
        return length >= prefix.length && Arrays.equals(data, 0, prefix.length, prefix, 0, prefix.length);
    }
}
