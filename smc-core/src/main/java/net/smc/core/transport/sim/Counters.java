package net.smc.core.transport.sim;

/** The mutable counters behind one address's {@link NodeCounters}; touched on the simulation's thread only. */
final class Counters {
    long sent;
    long copies;
    long duplicated;
    long delivered;
    long droppedByLoss;
    long droppedByPartition;
    long droppedByRadio;
    long droppedWhileDown;
    long droppedNoReceiver;

    void dropped(DropReason reason) {
        switch (reason) {
            case LOSS -> droppedByLoss++;
            case PARTITION -> droppedByPartition++;
            case RADIO -> droppedByRadio++;
            case SENDER_DOWN, RECEIVER_DOWN -> droppedWhileDown++;
            case NO_RECEIVER -> droppedNoReceiver++;
        }
    }

    NodeCounters snapshot() {
        return new NodeCounters(sent, copies, duplicated, delivered, droppedByLoss, droppedByPartition,
                droppedByRadio, droppedWhileDown, droppedNoReceiver);
    }
}
