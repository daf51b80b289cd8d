package net.smc.sim.experiment;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

import net.smc.core.message.MessageType;

/**
 * Where the CPU charged by {@link CpuCharge} went and what travelled: per cell, the charged time by
 * {@link Category} and the datagrams received by message kind; for the whole team, the datagrams and
 * bytes sent by kind. The diagnostic behind the experiment's {@code --verbose} report: it names the
 * busiest cell and what kept it busy, and which kinds of message the set-up exchanged.
 */
public final class CpuLedger {
    /** What a charged nanosecond was spent on. */
    public enum Category {
        /** Encoding and decoding messages. */
        CODEC,
        /** Ed25519 signatures of broadcasts. */
        SIGN,
        /** Ed25519 verifications of broadcasts. */
        VERIFY,
        /** HMAC-SHA256 of unicasts, at both ends. */
        MAC,
        /** First contact between two cells: signature, credential verification and X25519 agreement. */
        HANDSHAKE,
        /** Parsing and loading policy text. */
        POLICY_LOAD,
        /** Deflating policy text to send. */
        DEFLATE,
        /** Inflating policy text received deflated. */
        INFLATE,
        /** Offering {@code newUAV} to obligation policies. */
        CONDITION
    }

    private static final int KINDS = 256;
    private static final Category[] CATEGORIES = Category.values();

    private final List<double[]> nanos = new ArrayList<>();
    private final List<long[]> received = new ArrayList<>();
    private final List<long[]> unverified = new ArrayList<>();
    private final List<long[]> held = new ArrayList<>();
    /** Per cell, how many of the datagrams it held unchecked it checked later. */
    private final List<long[]> heldChecked = new ArrayList<>();
    private final List<String> names = new ArrayList<>();
    private final long[] sentCount = new long[KINDS];
    private final long[] sentBytes = new long[KINDS];
    private long hellos;
    private long helloBytes;

    /** Adds {@code ns} of {@code category} to cell number {@code node} (numbered from 0 as first seen). */
    void charge(int node, Category category, double ns) {
        grow(node);
        nanos.get(node)[category.ordinal()] += ns;
    }

    void sent(int type, long length) {
        if (type >= 0) {
            sentCount[type]++;
            sentBytes[type] += length;
        }
    }

    /** A step of a handshake (a security-layer HELLO, no message of the cells) of {@code length} bytes was sent. */
    void sentHello(long length) {
        hellos++;
        helloBytes += length;
    }

    /** Handshake steps sent, and their bytes. */
    public long hellos() {
        return hellos;
    }

    public long helloBytes() {
        return helloBytes;
    }

    void received(int node, int type) {
        grow(node);
        if (type >= 0) {
            received.get(node)[type]++;
        }
    }

    /** Cell {@code node} received a datagram of kind {@code type} and dropped it unchecked (it would ignore it). */
    void droppedUnverified(int node, int type) {
        received(node, type);
        if (type >= 0) {
            unverified.get(node)[type]++;
        }
    }

    /** Cell {@code node} received a datagram of kind {@code type} and held it unchecked, to read it first. */
    void heldUnverified(int node, int type) {
        received(node, type);
        if (type >= 0) {
            held.get(node)[type]++;
        }
    }

    /** Cell {@code node} checked a datagram it held. */
    void heldChecked(int node) {
        grow(node);
        heldChecked.get(node)[0]++;
    }

    void name(int node, String vehicle) {
        grow(node);
        names.set(node, vehicle);
    }

    private void grow(int node) {
        while (nanos.size() <= node) {
            nanos.add(new double[CATEGORIES.length]);
            received.add(new long[KINDS]);
            unverified.add(new long[KINDS]);
            held.add(new long[KINDS]);
            heldChecked.add(new long[1]);
            names.add(null);
        }
    }

    /** The cell charged the most CPU, or -1 when none was charged. */
    public int busiest() {
        int best = -1;
        double most = -1;
        for (int i = 0; i < nanos.size(); i++) {
            double t = total(i);
            if (t > most) {
                most = t;
                best = i;
            }
        }
        return best;
    }

    /** The vehicle that sends from cell {@code node}, or {@code "?"} when it never sent. */
    public String name(int node) {
        String n = node < names.size() ? names.get(node) : null;
        return n == null ? "?" : n;
    }

    /** Charged CPU of cell {@code node}, ms. */
    public double totalMillis(int node) {
        return total(node) / 1e6;
    }

    /** Charged CPU of cell {@code node} by category, ms (categories with none left out). */
    public Map<Category, Double> millisByCategory(int node) {
        Map<Category, Double> m = new EnumMap<>(Category.class);
        if (node >= 0 && node < nanos.size()) {
            double[] n = nanos.get(node);
            for (Category c : CATEGORIES) {
                if (n[c.ordinal()] > 0) {
                    m.put(c, n[c.ordinal()] / 1e6);
                }
            }
        }
        return m;
    }

    /** Datagrams cell {@code node} received, by message kind (a fragment counts as its message's kind). */
    public Map<String, Long> receivedByKind(int node) {
        return node >= 0 && node < received.size() ? byKind(received.get(node)) : Map.of();
    }

    /** Datagrams cell {@code node} received and dropped unchecked (it would have ignored them), by kind. */
    public Map<String, Long> droppedUnverifiedByKind(int node) {
        return node >= 0 && node < unverified.size() ? byKind(unverified.get(node)) : Map.of();
    }

    /** Datagrams cell {@code node} received and held unchecked, to read first, by kind. */
    public Map<String, Long> heldUnverifiedByKind(int node) {
        return node >= 0 && node < held.size() ? byKind(held.get(node)) : Map.of();
    }

    /** How many of the datagrams cell {@code node} held unchecked it checked later. */
    public long heldCheckedCount(int node) {
        return node >= 0 && node < heldChecked.size() ? heldChecked.get(node)[0] : 0;
    }

    /** Datagrams all cells held unchecked, to read first. */
    public long heldUnverifiedTotal() {
        return held.stream().mapToLong(counts -> java.util.Arrays.stream(counts).sum()).sum();
    }

    /** How many of the datagrams all cells held unchecked they checked later. */
    public long heldCheckedTotal() {
        return heldChecked.stream().mapToLong(c -> c[0]).sum();
    }

    /** Datagrams the team sent, by kind (a broadcast once). */
    public Map<String, Long> sentByKind() {
        return byKind(sentCount);
    }

    /** Bytes the team sent, by kind. */
    public Map<String, Long> sentBytesByKind() {
        return byKind(sentBytes);
    }

    private double total(int node) {
        double t = 0;
        for (double v : nanos.get(node)) {
            t += v;
        }
        return t;
    }

    private static Map<String, Long> byKind(long[] counts) {
        Map<String, Long> m = new TreeMap<>();
        for (int code = 0; code < KINDS; code++) {
            if (counts[code] > 0) {
                m.put(kindName(code), counts[code]);
            }
        }
        return m;
    }

    static String kindName(int code) {
        try {
            return MessageType.fromCode(code).name();
        } catch (IllegalArgumentException e) {
            return String.format(Locale.ROOT, "0x%02x", code);
        }
    }

    /** A few lines: the busiest cell's charged CPU by category and its inbox by kind, and the team's traffic by kind. */
    public String report() {
        int b = busiest();
        StringBuilder s = new StringBuilder();
        if (b < 0) {
            return "no CPU charged\n";
        }
        s.append(String.format(Locale.ROOT, "busiest cell %s: %.1f ms charged CPU:", name(b), totalMillis(b)));
        millisByCategory(b).forEach((c, ms) -> s.append(String.format(Locale.ROOT, " %s %.1f", c.name().toLowerCase(Locale.ROOT), ms)));
        s.append("\n  it received:");
        receivedByKind(b).forEach((k, n) -> s.append(' ').append(k).append(' ').append(n));
        Map<String, Long> dropped = droppedUnverifiedByKind(b);
        if (!dropped.isEmpty()) {
            s.append("\n  of which it dropped unchecked (it would ignore them):");
            dropped.forEach((k, n) -> s.append(' ').append(k).append(' ').append(n));
        }
        Map<String, Long> kept = heldUnverifiedByKind(b);
        if (!kept.isEmpty()) {
            s.append("\n  of which it held unchecked (read to choose whom to contact):");
            kept.forEach((k, n) -> s.append(' ').append(k).append(' ').append(n));
            s.append(", and checked ").append(heldCheckedCount(b)).append(" of them");
        }
        if (heldUnverifiedTotal() > 0) {
            s.append("\nteam held unchecked ").append(heldUnverifiedTotal()).append(" datagrams and checked ")
                    .append(heldCheckedTotal()).append(" of them");
        }
        s.append("\nteam sent (datagrams/bytes):");
        Map<String, Long> bytes = sentBytesByKind();
        sentByKind().forEach((k, n) -> s.append(' ').append(k).append(' ').append(n).append('/').append(bytes.get(k)));
        if (hellos > 0) {
            s.append(" HELLO ").append(hellos).append('/').append(helloBytes);
        }
        return s.append('\n').toString();
    }
}
