package net.smc.core.comm;

import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.Iterator;
import java.util.Map;
import java.util.function.Consumer;

import net.smc.core.transport.Address;

/**
 * Finds a critical message lost before its timeout, from the Acks of those sent after it to the same
 * peer (the idea of RACK, RFC 8985, on messages instead of segments): a cell's transport sends its
 * datagrams in the order they are handed to it, so when a message sent once is acknowledged, every
 * message sent once to the same peer before it should have been acknowledged too, unless the network
 * reordered them. Each of those still outstanding is suspected, once; the {@link MessageSender}
 * retransmits it if no Ack has come within a reordering window.
 *
 * <p>A policy file lost behind an assignment, or an assignment lost ahead of its files, so costs a
 * round trip and the window instead of the retransmission timeout (at least 50 ms in the team
 * protocols, against round trips of 8-16 ms on the set-up experiment's radio). A message whose
 * later companions were lost as well, or that was the last sent, still waits for its timeout.
 *
 * <p>Per peer, the messages sent once in send order; a settled or retransmitted one leaves its
 * queue when it reaches the head, so a queue holds at most the messages sent to its peer since
 * the oldest one still waiting for its first Ack (or still being retransmitted), and a peer with
 * nothing outstanding has none. Single-threaded, like its sender.
 */
final class LossDetector {
    private final Map<Address, ArrayDeque<Pending>> sentOnce = new HashMap<>();

    /** {@code p} was transmitted for the first time. */
    void sent(Pending p) {
        sentOnce.computeIfAbsent(p.to, a -> new ArrayDeque<>()).addLast(p);
    }

    /**
     * The first copy of {@code acked} was acknowledged: hands {@code suspect} every message sent
     * once to the same peer before it and neither acknowledged nor suspected yet.
     */
    void acked(Pending acked, Consumer<Pending> suspect) {
        ArrayDeque<Pending> queue = sentOnce.get(acked.to);
        if (queue == null) {
            return;
        }
        for (Iterator<Pending> it = queue.iterator(); it.hasNext(); ) {
            Pending p = it.next();
            if (p == acked) {
                break;
            }
            if (!done(p) && !p.suspected) {
                p.suspected = true;
                suspect.accept(p);
            }
        }
        trim(acked.to, queue);
    }

    /**
     * {@code acked}, sent again as a tail probe, was acknowledged: as {@link #acked}, the messages sent
     * once to the same peer before its first copy are suspected, if it is still held (when it is not,
     * every message before it was done already).
     */
    void ackedAgain(Pending acked, Consumer<Pending> suspect) {
        ArrayDeque<Pending> queue = sentOnce.get(acked.to);
        if (queue != null && queue.contains(acked)) {
            acked(acked, suspect);
        } else {
            settled(acked);
        }
    }

    /** {@code p} settled (acknowledged after a retransmission, or failed): its peer's queue lets go of what is done. */
    void settled(Pending p) {
        ArrayDeque<Pending> queue = sentOnce.get(p.to);
        if (queue != null) {
            trim(p.to, queue);
        }
    }

    private void trim(Address peer, ArrayDeque<Pending> queue) {
        while (!queue.isEmpty() && done(queue.peekFirst())) {
            queue.pollFirst();
        }
        if (queue.isEmpty()) {
            sentOnce.remove(peer);
        }
    }

    /** Forgets every message (the sender stopped). */
    void clear() {
        sentOnce.clear();
    }

    /** Messages held over all peers (for tests: the queues must not grow without bound). */
    int size() {
        return sentOnce.values().stream().mapToInt(ArrayDeque::size).sum();
    }

    private static boolean done(Pending p) {
        return p.settled || p.tries > 1;
    }
}
