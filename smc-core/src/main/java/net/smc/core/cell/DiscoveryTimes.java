package net.smc.core.cell;

import java.util.LinkedHashMap;
import java.util.Map;

import net.smc.core.comm.CommunicationManager;
import net.smc.core.transport.Address;

/**
 * When each of this cell's latest discoveries left it, by envelope id. A discovery reply names the
 * discovery it answers ({@code DiscoveryReply.inReplyTo}), so the time from that discovery's
 * departure to the reply's arrival is a round trip to the replying vehicle, unambiguous even when
 * the discovery was repeated (each repeat has its own id): the Message-Sender takes it as a sample
 * ({@code MessageSender.roundTrip}), and so knows the round trip to a vehicle before it assigns the
 * vehicle a role, and the cell's round trip before it repeats a discovery (Supervisor). Only a reply
 * that passed its check is measured (Recruiter, ReplyBatches), with the time it arrived.
 */
final class DiscoveryTimes {
    /** Discoveries remembered: far more than a reply can be late by at four a heartbeat period. */
    static final int KEPT = 32;

    private final Map<Long, Long> departures = new LinkedHashMap<>(KEPT * 2) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Long, Long> eldest) {
            return size() > KEPT;
        }
    };
    /** When the latest discovery left (far in the past: none yet). */
    private long lastDepartureMillis = Long.MIN_VALUE / 2;

    /** Discovery {@code id} was broadcast and leaves (its sender's queue through) at {@code departureMillis}. */
    void sent(long id, long departureMillis) {
        departures.put(id, departureMillis);
        lastDepartureMillis = departureMillis;
    }

    /** When the latest discovery left (far in the past: none yet). */
    long lastDepartureMillis() {
        return lastDepartureMillis;
    }

    /**
     * A checked reply from {@code from} to discovery {@code inReplyTo} arrived at {@code arrivedMillis}:
     * gives the sender its round trip when that discovery is one of this cell's latest. Whether it did.
     */
    boolean measure(CommunicationManager comm, Address from, long inReplyTo, long arrivedMillis) {
        Long departure = departures.get(inReplyTo);
        if (departure == null || arrivedMillis < departure) {
            return false;
        }
        comm.sender().roundTrip(from, arrivedMillis - departure);
        return true;
    }
}
