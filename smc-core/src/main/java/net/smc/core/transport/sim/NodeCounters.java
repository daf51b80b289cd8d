package net.smc.core.transport.sim;

/**
 * What the {@link InMemoryNetwork} did for one address (a snapshot). Each datagram copy ends in
 * exactly one of {@code delivered} or a drop counter, so the network-wide totals satisfy
 * {@code copies made == delivered + dropped()} once nothing is in flight.
 *
 * @param sent                 datagrams the node sent (one per unicast, one per broadcast)
 * @param copies               copies made of those: one per unicast, one per destination of a broadcast, plus duplicates
 * @param duplicated           extra copies made towards this node by duplication
 * @param delivered            copies handed to this node's receiver
 * @param droppedByLoss        copies to this node lost on the link
 * @param droppedByPartition   copies to this node cut off by a partition
 * @param droppedByRadio       copies to this node out of radio reach
 * @param droppedWhileDown     copies this node sent while crashed, and copies that arrived when nothing was attached here
 * @param droppedNoReceiver    copies that arrived before this node set a receiver
 */
public record NodeCounters(long sent, long copies, long duplicated, long delivered, long droppedByLoss,
                           long droppedByPartition, long droppedByRadio, long droppedWhileDown,
                           long droppedNoReceiver) {

    /** All zeros: a node that did nothing. */
    public static final NodeCounters ZERO = new NodeCounters(0, 0, 0, 0, 0, 0, 0, 0, 0);

    /** Every copy dropped for any reason. */
    public long dropped() {
        return droppedByLoss + droppedByPartition + droppedByRadio + droppedWhileDown + droppedNoReceiver;
    }

    /** The sum of two nodes' counters. */
    public NodeCounters plus(NodeCounters o) {
        return new NodeCounters(sent + o.sent, copies + o.copies, duplicated + o.duplicated,
                delivered + o.delivered, droppedByLoss + o.droppedByLoss,
                droppedByPartition + o.droppedByPartition, droppedByRadio + o.droppedByRadio,
                droppedWhileDown + o.droppedWhileDown, droppedNoReceiver + o.droppedNoReceiver);
    }
}
