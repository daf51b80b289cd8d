package net.smc.core.router;

import net.smc.core.message.Envelope;

/**
 * Something in a cell that receives packets from the {@link MessageRouter}: a role, or another
 * object such as the Role-Manager. The router knows a subscriber by identity (the object itself,
 * not {@code equals}), so one object is one subscriber however many registrations it makes.
 */
@FunctionalInterface
public interface Subscriber {
    /**
     * Called once for each dispatched packet this subscriber's registrations select, on the cell's
     * thread. An exception thrown here is counted and logged by the router; the other subscribers
     * still receive the packet.
     */
    void receive(Envelope envelope);
}
