package net.smc.core.comm;

import java.util.PriorityQueue;
import java.util.function.Consumer;

import net.smc.core.transport.Cancellable;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Scheduler;

/**
 * The retransmission timer: one scheduler task for all outstanding messages, armed for the
 * earliest deadline, instead of one task per message. With thousands of messages in flight a
 * task each would cost a schedule and a cancel per message (on a real timer, a lock and a heap
 * operation on another thread); here an Ack costs nothing but marking its message settled.
 *
 * <p>Deadlines sit in a heap, ordered by time and then by insertion, so ties fire in send order
 * and a simulation is deterministic. An entry whose message was settled, or re-armed for a later
 * try, is stale and skipped when it comes up (lazy deletion): the heap holds at most the messages
 * sent within one timeout. The timer also tolerates a scheduler that fires a little early: what
 * is not yet due is simply re-armed.
 */
final class RetryTimer {
    private record Entry(long deadlineMillis, long seq, Pending pending, int tries) {
        boolean stale() {
            return pending.settled || pending.tries != tries;
        }
    }

    private static final long FIRING = Long.MIN_VALUE;

    private final Clock clock;
    private final Scheduler scheduler;
    private final Consumer<Pending> onTimeout;
    private final PriorityQueue<Entry> heap = new PriorityQueue<>((a, b) -> a.deadlineMillis != b.deadlineMillis
            ? Long.compare(a.deadlineMillis, b.deadlineMillis) : Long.compare(a.seq, b.seq));
    private long seq;
    private Cancellable armed;
    /** The time the armed task is for; Long.MAX_VALUE when none, FIRING while timeouts are handled. */
    private long armedForMillis = Long.MAX_VALUE;

    RetryTimer(Clock clock, Scheduler scheduler, Consumer<Pending> onTimeout) {
        this.clock = clock;
        this.scheduler = scheduler;
        this.onTimeout = onTimeout;
    }

    /** Calls {@code onTimeout} for {@code pending} at its deadline, unless it settled or was re-armed by then. */
    void watch(Pending pending) {
        heap.add(new Entry(pending.deadlineMillis, seq++, pending, pending.tries));
        if (pending.deadlineMillis < armedForMillis && armedForMillis != FIRING) {
            arm(pending.deadlineMillis);
        }
    }

    /** Cancels the timer and forgets every deadline. */
    void stop() {
        if (armed != null) {
            armed.cancel();
            armed = null;
        }
        armedForMillis = Long.MAX_VALUE;
        heap.clear();
    }

    /** Deadlines held, stale ones included (for tests: the heap must not grow without bound). */
    int size() {
        return heap.size();
    }

    private void fire() {
        armed = null;
        armedForMillis = FIRING;
        long now = clock.nowMillis();
        try {
            for (Entry e = heap.peek(); e != null && e.deadlineMillis <= now; e = heap.peek()) {
                heap.poll();
                if (!e.stale()) {
                    onTimeout.accept(e.pending);
                }
            }
        } finally {
            armedForMillis = Long.MAX_VALUE;
            Entry next = dropStaleHead();
            if (next != null) {
                arm(next.deadlineMillis);
            }
        }
    }

    private Entry dropStaleHead() {
        Entry head = heap.peek();
        while (head != null && head.stale()) {
            heap.poll();
            head = heap.peek();
        }
        return head;
    }

    private void arm(long deadlineMillis) {
        if (armed != null) {
            armed.cancel();
        }
        armedForMillis = deadlineMillis;
        armed = scheduler.schedule(Math.max(0, deadlineMillis - clock.nowMillis()), this::fire);
    }
}
