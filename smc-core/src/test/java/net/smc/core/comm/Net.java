package net.smc.core.comm;

import java.util.function.BooleanSupplier;

/** A network of cells for the reliable-delivery suite: simulated, or real UDP on loopback. */
interface Net extends AutoCloseable {

    /** Link faults, per datagram: probabilities from 0 to 1. */
    record Faults(double loss, double duplication, double reorder) {
        static final Faults NONE = new Faults(0, 0, 0);
    }

    /** A new cell with this vehicle id. */
    Peer peer(String vehicleId);

    /** Runs {@code action} on {@code peer}'s thread and returns after it ran. */
    void onCell(Peer peer, Runnable action);

    /** Lets the network run until {@code done} holds; fails the test if it does not within {@code withinMillis} (virtual or real). */
    void awaitUntil(BooleanSupplier done, long withinMillis);

    /** Makes {@code peer} unreachable: crashed in simulation, closed on UDP. */
    void makeUnreachable(Peer peer);

    /** How late, beyond the settings' bound, a failure may be reported (the real scheduler's lateness). */
    long slackMillis();

    @Override
    void close();
}
