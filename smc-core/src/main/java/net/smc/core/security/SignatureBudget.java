package net.smc.core.security;

import java.util.HashMap;
import java.util.Map;
import net.smc.core.transport.Address;

/**
 * How many signature checks a cell spends, per source address and in all, per second: a signed
 * datagram costs about a millisecond of Ed25519, so without a bound a flood of forged ones (each
 * cheap to make: a recorded datagram with a byte changed) takes the cell's whole thread. Token
 * buckets on the cell's clock: each source may spend {@code perSource} checks a second (with a burst
 * as large), all sources together {@code total}. A datagram over budget is dropped before any
 * signature is checked. One flooding source spends its own budget only; a flood from many forged
 * source addresses can spend the total and so delay strangers (new vehicles, discovery), never the
 * traffic of established sessions, which is MAC'd and needs no signature.
 *
 * <p>Single-threaded: it belongs to its cell's thread.
 */
final class SignatureBudget {
    /** Signature checks a second one source address may cause. */
    static final int PER_SOURCE_PER_SECOND = 20;
    /** Signature checks a second in all. */
    static final int TOTAL_PER_SECOND = 200;
    private static final int MAX_SOURCES = 4096;

    private final int perSource;
    private final int total;
    private final Map<Address, Bucket> sources = new HashMap<>();
    private final Bucket all;

    SignatureBudget(int perSource, int total) {
        if (perSource < 1 || total < perSource) {
            throw new IllegalArgumentException("signature budget: per source " + perSource + " must be at least 1 and at most the total " + total);
        }
        this.perSource = perSource;
        this.total = total;
        this.all = new Bucket(total, Long.MIN_VALUE);
    }

    /** Takes one check for {@code from} at {@code nowMillis}; false (and nothing taken) when over budget. */
    boolean take(Address from, long nowMillis) {
        Bucket b = sources.get(from);
        if (b == null) {
            if (sources.size() >= MAX_SOURCES) {
                sources.values().removeIf(x -> x.full(perSource, nowMillis));
                if (sources.size() >= MAX_SOURCES) {
                    sources.clear();   // a flood of forged addresses: the total bound still holds
                }
            }
            b = new Bucket(perSource, nowMillis);
            sources.put(from, b);
        }
        b.refill(perSource, nowMillis);
        all.refill(total, nowMillis);
        if (b.tokens < 1 || all.tokens < 1) {
            return false;
        }
        b.tokens--;
        all.tokens--;
        return true;
    }

    /** Tokens, refilled at {@code rate} per second up to {@code rate}. */
    private static final class Bucket {
        double tokens;
        long lastMillis;

        Bucket(int rate, long nowMillis) {
            this.tokens = rate;
            this.lastMillis = nowMillis;
        }

        void refill(int rate, long nowMillis) {
            if (lastMillis == Long.MIN_VALUE || nowMillis < lastMillis) {
                lastMillis = nowMillis;
                return;
            }
            tokens = Math.min(rate, tokens + (nowMillis - lastMillis) * rate / 1000.0);
            lastMillis = nowMillis;
        }

        boolean full(int rate, long nowMillis) {
            refill(rate, nowMillis);
            return tokens >= rate;
        }
    }
}
