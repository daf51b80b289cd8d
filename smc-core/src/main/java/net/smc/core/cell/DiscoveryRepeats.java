package net.smc.core.cell;

import java.util.function.BooleanSupplier;
import net.smc.core.transport.Cancellable;

/**
 * The early repeats of a manager's discovery (Supervisor). Discovery and its replies travel
 * unacknowledged: when either is lost, a seat would stay open until the next tick's discovery, a
 * whole heartbeat period later, on every level of the tree below it. So, from each start of
 * discovery, while a seat stays open it is discovered again when the answers to the discovery that
 * started it should have come: the cell's retransmission timeout ({@code
 * MessageSender.cellTimeoutMillis}: its measured round trips, which the replies to its discoveries
 * feed, plus four deviations, no shorter than the timing's minimum; the fixed first timeout while
 * nothing was measured) after that discovery left; then after twice that, and so on while the wait is
 * below a heartbeat period; from then on the tick discovers every period. The first repeat is
 * brought forward when replies measured meanwhile shorten the estimate (a commander's first
 * discovery is timed before any round trip is known). Each repeat goes through the Supervisor's
 * rediscovery: none while capability requests are out, and within its rate limit.
 */
final class DiscoveryRepeats {
    private final TeamContext ctx;
    /** Whether a seat is still open for a repeat to look for (and the cell still running). */
    private final BooleanSupplier stillOpen;
    private final Runnable rediscover;
    private boolean stopped;
    /** The next repeat, or null. */
    private Cancellable due;
    /** When {@link #due} fires, and whether it is the first repeat after the discovery that left at {@link #fromMillis}. */
    private long atMillis;
    private boolean first;
    private long fromMillis;

    DiscoveryRepeats(TeamContext ctx, BooleanSupplier stillOpen, Runnable rediscover) {
        this.ctx = ctx;
        this.stillOpen = stillOpen;
        this.rediscover = rediscover;
    }

    /** A discovery starts, leaving at {@code discoveryLeftMillis}: its repeats are timed from then (none if some are under way). */
    void start(long discoveryLeftMillis) {
        if (due != null || stopped) {
            return;
        }
        long wait = ctx.comm().sender().cellTimeoutMillis();
        fromMillis = discoveryLeftMillis;
        first = true;
        arm(discoveryLeftMillis + wait, wait);
    }

    /** A discovery reply gave a round trip: a first repeat due later than the estimate now says is brought forward. */
    void roundTripMeasured() {
        if (due == null || !first) {
            return;
        }
        long wait = ctx.comm().sender().cellTimeoutMillis();
        long at = fromMillis + wait;
        if (at < atMillis) {
            due.cancel();
            due = null;
            arm(at, wait);
        }
    }

    /** The cell stops: no repeat any more. */
    void stop() {
        stopped = true;
        if (due != null) {
            due.cancel();
            due = null;
        }
    }

    private void arm(long at, long waitMillis) {
        if (stopped || waitMillis >= ctx.timing().comTimeoutMillis()) {
            return;
        }
        long now = ctx.clock().nowMillis();
        atMillis = Math.max(now, at);
        due = ctx.scheduler().schedule(atMillis - now, () -> {
            due = null;
            first = false;
            if (stillOpen.getAsBoolean()) {
                rediscover.run();
                arm(ctx.clock().nowMillis() + 2 * waitMillis, 2 * waitMillis);
            }
        });
    }
}
