package net.smc.core.cell;

import net.smc.core.mission.Mission;
import net.smc.core.mission.Parameter;
import net.smc.core.mission.TeamParameters;

/**
 * The protocol's times, all derived from the mission's {@code comTimeout} (the heartbeat period,
 * ms) and {@code failureTimeout} (silence after which a vehicle is taken for failed, ms), and the
 * number of backup commanders.
 *
 * <ul>
 *   <li>Every cell acts once per {@code comTimeout} (a "tick"): children send heartbeats, parents
 *       answer each (a status, or a bare echo while the child holds the current status; at the tick
 *       when a child's heartbeat went unanswered for a period and a half), managers check their
 *       children and discover.</li>
 *   <li>A parent declares a child failed after {@code failureTimeout} without a heartbeat.</li>
 *   <li>A child's lease lasts {@code failureTimeout - comTimeout / 2} from the <em>sending</em> of
 *       its latest heartbeat that a status or an echo echoed: the parent heard that heartbeat after it was
 *       sent, so the child stops counting as a holder before the parent can give its seat to another
 *       vehicle, whatever the latency (the half heartbeat covers clocks that run at slightly
 *       different rates).</li>
 *   <li>Backup {@code k} (from 0) takes over after {@code failureTimeout + (k + 1) * comTimeout} without
 *       hearing the commander; a child drops its roles for good after
 *       {@code failureTimeout + (backups + 2) * comTimeout}, so a take-over finds the team intact.</li>
 *   <li>An acting commander beacons (broadcasts discovery) at least every {@code beaconTicks} ticks,
 *       so two commanders that can hear each other meet within that time plus latency.</li>
 * </ul>
 */
public record Timing(long comTimeoutMillis, long failureTimeoutMillis, int backups) {
    /** Ticks between an acting commander's beacons when its team is complete. */
    public static final int BEACON_TICKS = 4;
    /** Ticks between roster updates to backups, when nothing changed. */
    public static final int ROSTER_TICKS = 4;

    public Timing {
        TeamParameters.timing(comTimeoutMillis, failureTimeoutMillis, backups).ifPresent(problem -> {
            throw new IllegalArgumentException(problem.message());
        });
    }

    /**
     * The timing a mission gives: its {@code comTimeout} and {@code failureTimeout} parameters, and
     * {@code backups} if it has one (else 1).
     *
     * @throws IllegalArgumentException naming the parameter when one is missing or not a number
     */
    public static Timing of(Mission mission) {
        long backups = mission.parameter("backups").map(p -> TeamParameters.count(p.name(), p.value())).orElse(1L);
        TeamParameters.timing(number(mission, "comTimeout"), number(mission, "failureTimeout"), backups)
                .ifPresent(problem -> {
                    throw new IllegalArgumentException(problem.message());
                });
        return new Timing(number(mission, "comTimeout"), number(mission, "failureTimeout"), (int) backups);
    }

    private static long number(Mission mission, String name) {
        Parameter p = mission.parameter(name).orElseThrow(() -> new IllegalArgumentException("mission '"
                + mission.instanceName() + "' has no parameter '" + name + "'; the team protocols need it (ms)"));
        return TeamParameters.millis(p.name(), p.value());
    }

    /**
     * Retransmission of the protocols' critical messages, paced by the heartbeat period: first try
     * after comTimeout/5 at most, doubling up to comTimeout, eight tries. The first try's timeout
     * follows the measured round trips (the peer's, else the cell's over its other peers; see
     * {@link net.smc.core.comm.SenderSettings}), no shorter than {@link #minRetransmissionMillis()}.
     * A message to a silent peer is given up on at the time the fixed schedule would (about 6.4
     * comTimeouts, jittered), within {@link net.smc.core.comm.SenderSettings#failureBoundMillis()}.
     */
    public net.smc.core.comm.SenderSettings senderSettings() {
        long first = Math.max(1, comTimeoutMillis / 5);
        return new net.smc.core.comm.SenderSettings(first, 2.0, Math.max(first, comTimeoutMillis), 8, 0.2,
                Math.max(30_000, 20 * failureTimeoutMillis), 65_536, minRetransmissionMillis());
    }

    /**
     * The shortest first retransmission timeout a round-trip estimate may set: half the fixed one
     * (50 ms for a 500 ms heartbeat period, against round trips of 8-16 ms on the set-up
     * experiment's radio). The timer starts when a message has left the sender's radio, so the
     * sender's own queue needs no margin here; this one covers the receiver's, which the round trips
     * measured on a quiet path (a discovery reply, the first Acks) do not show: an Ack waits while its
     * sender's CPU loads a policy file (about 5 ms a kilobyte) and behind what its radio is sending
     * (a datagram behind 3 KB of policy files waits about 10 ms; a manager seating ten children
     * queues about 35 KB). Shorter, retransmissions are spurious more often, and a spurious copy of a
     * policy file fills the queue it waits in: with three tenths (30 ms) a 1,000-role set-up sent
     * about 70 more retransmissions than with the fixed timeout (of about 6,500 critical messages),
     * with half about 20 more.
     */
    public long minRetransmissionMillis() {
        return Math.max(1, Math.max(1, comTimeoutMillis / 5) / 2);
    }

    /**
     * How long a manager keeps a seat reserved for a vehicle it sent an assignment to, without an
     * answer: long enough for the assignment to arrive late, the vehicle to fetch policies for a
     * failure timeout, and its answer to arrive late, so that a vehicle never holds a seat its
     * manager has given to another.
     */
    public long pendingMillis() {
        return 2 * senderSettings().failureBoundMillis() + failureTimeoutMillis + comTimeoutMillis;
    }

    /**
     * How long a manager remembers that its policies passed over a free vehicle: four failure
     * timeouts (12 s in the reconnaissance mission). Within it a vehicle that keeps answering
     * discovery is put to the policies again only when what it presents (capability summary,
     * credential), the policies (their version) or the manager's open seats change; the bound covers
     * conditions that read other state (counts, the time, what a task observed).
     */
    public long refusalMillis() {
        return 4 * failureTimeoutMillis;
    }

    /**
     * How long a manager with {@code siblings} managers of its role (itself included) takes, once
     * its role has started, only the free vehicles of its own share of the ring (ReplyBatches): a
     * hundredth of {@code comTimeout} per sibling, 50 ms for ten siblings and a 500 ms period, 10 ms
     * for two. The siblings' parent sends them their assignments and files one after another, so
     * they start spread over a time that grows with their number, and each gives its seats one after
     * another; the time is short against a heartbeat period, and never longer than the first
     * retransmission timeout of the critical messages (100 ms), so a manager whose share is short of
     * vehicles waits little before it takes the spare ones of the others' shares. 0 (no such time)
     * for a manager without siblings.
     */
    public long ownShareMillis(int siblings) {
        if (siblings < 1) {
            throw new IllegalArgumentException("siblings is " + siblings + "; a manager counts itself, so it is 1 or more");
        }
        return siblings == 1 ? 0 : Math.min(siblings * comTimeoutMillis / 100, senderSettings().initialTimeoutMillis());
    }

    public long leaseMillis() {
        return failureTimeoutMillis - comTimeoutMillis / 2;
    }

    public long takeoverMillis(int rank) {
        return failureTimeoutMillis + (rank + 1L) * comTimeoutMillis;
    }

    public long orphanMillis() {
        return failureTimeoutMillis + (backups + 2L) * comTimeoutMillis;
    }
}
