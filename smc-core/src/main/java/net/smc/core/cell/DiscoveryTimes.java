package net.smc.core.cell;

import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;

import net.smc.core.comm.CommunicationManager;
import net.smc.core.transport.Address;

/**
 * When each of this cell's latest discoveries left it, by envelope id. A discovery reply names the
 * discovery it answers ({@code DiscoveryReply.inReplyTo}), so the time from that discovery's
 * departure to the reply's arrival is a round trip to the replying vehicle, unambiguous even when
 * the discovery was repeated (each repeat has its own id): the Message-Sender takes it as a sample
 * ({@code MessageSender.roundTrip}), and so knows the round trip to a vehicle before it assigns the
 * vehicle a role, and the cell's round trip before it repeats a discovery (Supervisor). Only a reply
 * that passed its check is measured (Recruiter, ReplyBatches), with the time its first copy arrived,
 * and only once per discovery and address: a network duplicate or a replay of it, later, is no sample.
 */
final class DiscoveryTimes {
    /** Discoveries remembered: far more than a reply can be late by at four a heartbeat period. */
    static final int KEPT = 32;

    /** One discovery: when it left, and the addresses whose replies to it were measured. */
    private record Sent(long departureMillis, Set<Address> measured) {
    }

    private final Map<Long, Sent> departures = new LinkedHashMap<>(KEPT * 2) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Long, Sent> eldest) {
            return size() > KEPT;
        }
    };
    /** When the latest discovery left (far in the past: none yet). */
    private long lastDepartureMillis = Long.MIN_VALUE / 2;

    /** Discovery {@code id} was broadcast and leaves (its sender's queue through) at {@code departureMillis}. */
    void sent(long id, long departureMillis) {
        departures.put(id, new Sent(departureMillis, new HashSet<>()));
        lastDepartureMillis = departureMillis;
    }

    /**
     * Whether {@code id} is one of this cell's latest discoveries: a reply naming another answers a
     * discovery long past or another manager's (a replay of an authentic but stale reply), and is
     * not decided on.
     */
    boolean answersOurs(long id) {
        return departures.containsKey(id);
    }

    /** When the latest discovery left (far in the past: none yet). */
    long lastDepartureMillis() {
        return lastDepartureMillis;
    }

    /**
     * A checked reply from {@code from} to discovery {@code inReplyTo} arrived at {@code arrivedMillis}:
     * gives the sender its round trip when that discovery is one of this cell's latest and no reply
     * from {@code from} to it was measured before. Whether it did.
     */
    boolean measure(CommunicationManager comm, Address from, long inReplyTo, long arrivedMillis) {
        Sent sent = departures.get(inReplyTo);
        if (sent == null || arrivedMillis < sent.departureMillis() || !sent.measured().add(from)) {
            return false;
        }
        comm.sender().roundTrip(from, arrivedMillis - sent.departureMillis());
        return true;
    }
}
