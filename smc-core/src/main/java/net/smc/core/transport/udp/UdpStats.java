package net.smc.core.transport.udp;

import java.util.concurrent.atomic.LongAdder;

/** The live counters behind {@link UdpCounters}, bumped from the event loop and the cell's thread. */
final class UdpStats {
    final LongAdder sent = new LongAdder();
    final LongAdder broadcastsSent = new LongAdder();
    final LongAdder sendFailures = new LongAdder();
    final LongAdder refusedOversize = new LongAdder();
    final LongAdder delivered = new LongAdder();
    final LongAdder ownBroadcastsFiltered = new LongAdder();
    final LongAdder droppedOversize = new LongAdder();
    final LongAdder droppedNoReceiver = new LongAdder();
    final LongAdder droppedClosed = new LongAdder();
    final LongAdder droppedRejected = new LongAdder();
    final LongAdder droppedBacklog = new LongAdder();

    UdpCounters snapshot() {
        return new UdpCounters(sent.sum(), broadcastsSent.sum(), sendFailures.sum(), refusedOversize.sum(),
                delivered.sum(), ownBroadcastsFiltered.sum(), droppedOversize.sum(), droppedNoReceiver.sum(),
                droppedClosed.sum(), droppedRejected.sum(), droppedBacklog.sum());
    }
}
