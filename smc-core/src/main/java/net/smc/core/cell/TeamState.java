package net.smc.core.cell;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.LongSupplier;

import net.smc.core.capability.CapabilitySummary;
import net.smc.core.message.Identity;
import net.smc.core.message.RoleAssignment;
import net.smc.core.message.Roster;
import net.smc.core.transport.Address;

/**
 * The mutable state the parts of the team protocols share: where this cell stands in the tree (its
 * seats, parent, lease, commander and epoch), and as a manager the seats it owns and the children
 * holding them. Each part reads it; each field says which parts write it. Only the cell's thread
 * touches it.
 */
final class TeamState {
    private final TeamContext ctx;

    /**
     * Grows whenever what places this cell in the tree changes: {@link #parent}, {@link #acting},
     * {@link #seats}, {@link #leaseUntilMillis} (but for a renewal that only moves its end later:
     * a reader that finds the end it read has passed reads it again), and as a manager which
     * children it has and their seats. Every writer of those calls {@link #linksChanged()}; checks
     * that read a thousand cells (a simulation's invariants) re-read only the cells whose version
     * moved, told by {@link LinkVersion#listener} as it moves.
     */
    final LinkVersion linkVersion = new LinkVersion();

    // Where this cell stands (written by Assignee, Membership, BackupCommander, Merge, Seating).
    boolean acting;
    long epoch;
    String commander;
    Parent parent;
    /** The lease from the parent runs until then: the send time of the latest echoed heartbeat + the lease. */
    long leaseUntilMillis;
    /** Whether the SUSPENDED event for the current lapse was emitted. */
    boolean lapseNoted;
    /** When the parent was last heard (its latest status). */
    long lastStatusMillis;
    boolean left;
    final List<Seat> seats = new ArrayList<>();
    Identity identity;
    /** The role assignment this cell is taking (waiting for its policies), or null. */
    Incoming incoming;
    /**
     * The manager of the latest role assignment this cell began to take (Assignee), and that
     * assignment's message id: a copy of an earlier one from the same manager that arrives after it
     * (a retransmission that got through late) is no longer what the manager means.
     */
    String lastAssignmentFrom;
    long lastAssignmentId;
    /** This cell's ancestors as its parent last told them: the parent first, the commander last. */
    List<String> ancestors = List.of();
    List<Object> handedOver = List.of();
    List<Object> reportedState = List.of();
    int teamSize;
    long ticks;
    /**
     * The version of the parent's status this cell holds, and the parent it came from (a version
     * means nothing from another parent): named in each heartbeat (Membership).
     */
    long statusVersionHeld;
    String statusVersionFrom;

    // As a manager (written by Recruiter, Supervisor, Reports, Seating).
    /** What this cell last told its children in a status (all but the echo), and its version (Supervisor). */
    StatusContent statusContent;
    long statusVersion;
    final Map<Seat, Owned> owned = new TreeMap<>();
    final Map<String, Child> children = new TreeMap<>();
    final Map<String, PendingCapability> capabilityRequests = new HashMap<>();
    final Map<String, Heard> heard = new HashMap<>();
    /**
     * The vehicles whose discovery replies the transport holds unchecked, by the vehicle each claims
     * to be: where the reply came from and when (ReplyBatches.addUnchecked). Nothing here is proven:
     * it chooses only whose reply to check; a reply is acted on once checked (then it is in
     * {@link #heard}).
     */
    final Map<String, Unchecked> unchecked = new HashMap<>();
    /** When this cell's latest discoveries left it: a reply to one is a round trip (Recruiter, ReplyBatches, Supervisor). */
    final DiscoveryTimes discoveries = new DiscoveryTimes();
    /**
     * Vehicles the policies wanted asked for their full description, by the roles they were wanted
     * for, while as many requests for those roles were out as the role has open seats and a margin
     * (Recruiter): asked, oldest first, when a request out ends without filling a seat.
     */
    final Map<String, Set<String>> deferredAsks = new LinkedHashMap<>();
    /**
     * Children's requests for policy files of this cell's subtree that are still on their way to it
     * (it fetches them after taking its role), by URI: answered when the file arrives (Recruiter).
     */
    final Map<String, List<ParkedRequest>> parkedPolicyRequests = new HashMap<>();
    /**
     * When the discovery this cell sent as the assignment of a role that manages others arrived left
     * it, with the role's files still on their way (Assignee; far in the past: never), and the vehicles that
     * answered before the role started, which its policies decide on once it has (Recruiter).
     */
    long earlyDiscoveryMillis = Long.MIN_VALUE / 2;
    final Set<String> earlyReplies = new LinkedHashSet<>();
    /**
     * The discoveries this free vehicle answered lately, by manager: withdrawn when it takes a role
     * from another (Assignee), so that the managers do not offer it a seat it would refuse.
     */
    final Map<String, Answered> answered = new HashMap<>();

    /** A discovery answered: the manager's address, the discovery's id, when. */
    record Answered(Address address, long discovery, long atMillis) {
    }
    /**
     * The end of this manager's time of taking only its own share of the ring (a short time after
     * its role started; far in the past: none): a vehicle of a sibling's share is decided on only once
     * it has answered since (ReplyBatches.beginOwnShare).
     */
    long ownShareUntilMillis = Long.MIN_VALUE / 2;
    /** Free vehicles this cell's policies passed over when they were discovered, by vehicle (Recruiter). */
    final Map<String, Refusal> refused = new HashMap<>();
    final Map<String, List<Object>> handover = new HashMap<>();
    /**
     * Former children and assignees that may still name this cell as their parent (a Leave can be
     * lost), until their lease would have run out: taking a role from one of them could close a
     * cycle in the parent relation.
     */
    final Map<String, Long> abandoned = new HashMap<>();
    MissionState missionState;
    /** Whether the last tick found an open seat (a DISCOVERING event marks each start). */
    boolean discovering;
    /** Recruiting held by policy ({@code root/discovery hold}): as a manager, no discovery is sent. */
    boolean recruitingHeld;

    // As a backup commander (written by BackupCommander, Membership, Seating).
    Roster roster;
    int backupRank = -1;

    record Parent(String vehicle, Address address) {
    }

    /** A status's content but its echo: when it differs from the last, the status's version grows. */
    record StatusContent(Identity identity, String commander, long epoch, int teamSize, List<String> ancestors) {
    }

    record Incoming(String from, Address address, long envelopeId, RoleAssignment assignment, long sinceMillis) {
    }

    /** Forgets what {@code vehicle} answered discovery with, checked or held unchecked: it no longer holds. */
    void forgetAnswer(String vehicle) {
        heard.remove(vehicle);
        unchecked.remove(vehicle);
    }

    /** A child's policy request waiting for the file to reach this cell. */
    record ParkedRequest(Address from, long envelopeId, int version, long atMillis) {
    }

    /**
     * A checked discovery reply: what the vehicle can do, the role it holds now (empty when it is
     * free; else it takes only a seat of a role ranked before it, {@link #couldTake}), and when it came.
     */
    record Heard(CapabilitySummary summary, String holds, long atMillis) {
        boolean free() {
            return holds.isEmpty();
        }
    }

    /**
     * Whether the vehicle heard as {@code h} would take a seat of {@code role}: a free vehicle any, one
     * holding a role only a role ranked before it (it moves up, Assignee.promotion, and refuses the rest).
     */
    static boolean couldTake(Heard h, String role, Slots slots) {
        return h.free() || slots.mission().role(h.holds()).isPresent() && slots.rank(role) < slots.rank(h.holds());
    }

    /**
     * A discovery reply held unchecked: the address it came from (the key to check it by), when it
     * came (its first copy: a later copy of the same answer is not held again), and the discovery it
     * answers (its round trip is measured once it passes its check).
     */
    record Unchecked(Address from, long atMillis, long inReplyTo) {
    }

    /**
     * A free vehicle this cell passed over: when it replied with {@code summary} and
     * {@code credential} (compared by value; {@code Nil} when it presented none), the policies at
     * {@code policyVersion} asked for no open seat of the {@code openSeats} this cell had, or its
     * full description met the requirement of none they asked for.
     */
    record Refusal(CapabilitySummary summary, Object credential, long policyVersion, List<Seat> openSeats, long atMillis) {
        /** Whether the same decision stands: the same vehicle, policies and open seats, within {@code maxMillis}. */
        boolean stands(Refusal now, long maxMillis) {
            return summary.equals(now.summary) && credential.equals(now.credential) && policyVersion == now.policyVersion
                    && openSeats.equals(now.openSeats) && now.atMillis - atMillis < maxMillis;
        }
    }

    /** The key of a refusal now: what the vehicle presented, the policies' version and this cell's open seats. */
    Refusal refusal(CapabilitySummary summary, Object credential, long now) {
        return new Refusal(summary, credential, ctx.host().policyVersion(), owned.keySet().stream().filter(this::open).toList(),
                now);
    }

    static final class PendingCapability {
        final Set<String> roles = new LinkedHashSet<>();
        final long sinceMillis;

        PendingCapability(long sinceMillis) {
            this.sinceMillis = sinceMillis;
        }
    }

    /** One seat this cell owns: who holds it, or who is being given it. */
    static final class Owned {
        String holder;
        String pendingFor;
        long pendingSince;
    }

    static final class Child {
        final String vehicle;
        Address address;
        long lastHeard;
        List<Seat> seats = List.of();
        /**
         * What the vehicle presented of its capabilities (its resources and tasks: all a seat's
         * requirement reads), from its discovery reply or its full description; null until known.
         */
        CapabilitySummary description;
        List<Object> state = List.of();
        Map<String, Integer> subtree;
        int size = 1;
        int hosted;
        /** Envelope id of the latest heartbeat heard from it, echoed in every status. */
        long lastHeartbeat;
        /** The version of this cell's status the child's latest heartbeat says it holds (0: none). */
        long statusVersionHeld;
        /** When this cell last sent it a status (far in the past: never). */
        long statusSentMillis = Long.MIN_VALUE / 2;
        /**
         * Whether its last report agreed with this cell's table. Its lease is renewed (its heartbeats
         * echoed) only then, so a child that claims a seat given to another stops counting until it
         * has given that seat back.
         */
        boolean consistent = true;
        /** Envelope id of the child's message that confirmed each seat (its ids only grow). */
        final Map<Seat, Long> confirmedBy = new HashMap<>();

        Child(String vehicle) {
            this.vehicle = vehicle;
        }
    }

    TeamState(TeamContext ctx) {
        this.ctx = ctx;
    }

    /** Records a change of the parent, command, lease, seats, children or their seats (see {@link #linkVersion}). */
    void linksChanged() {
        linkVersion.value++;
        if (linkVersion.listener != null) {
            linkVersion.listener.run();
        }
    }

    /** {@link #linkVersion}'s counter, and who is told when it moves (null: no one). */
    static final class LinkVersion implements LongSupplier {
        private long value;
        Runnable listener;

        @Override
        public long getAsLong() {
            return value;
        }
    }

    /** Free: no parent, no role, not commanding, not taking a role. */
    boolean free() {
        return parent == null && !acting && seats.isEmpty() && incoming == null;
    }

    /** Whether the lease from the parent has run out: this cell's seats do not count until renewed. */
    boolean suspended() {
        return parent != null && !acting && ctx.clock().nowMillis() > leaseUntilMillis;
    }

    /** Whether the holder of a secondary seat holds it beside its own primary role. */
    boolean hosted(Seat seat, String holder) {
        if (!ctx.slots().role(seat.role()).isSecondary()) {
            return false;
        }
        List<Seat> held = holder.equals(ctx.self()) ? seats : children.containsKey(holder) ? children.get(holder).seats : List.of();
        return held.stream().anyMatch(s -> !ctx.slots().role(s.role()).isSecondary());
    }

    /** The seat being given to {@code vehicle} now (an assignment sent, no answer yet), if any. */
    Optional<Seat> seatGivenTo(String vehicle) {
        return owned.entrySet().stream().filter(e -> vehicle.equals(e.getValue().pendingFor)).map(Map.Entry::getKey).findFirst();
    }

    /** Whether a seat could go to a newly found vehicle: vacant, or only hosted, and nobody is being given it. */
    boolean open(Seat seat) {
        Owned o = owned.get(seat);
        return o != null && o.pendingFor == null && (o.holder == null || hosted(seat, o.holder));
    }

    boolean hasVacancy() {
        return owned.keySet().stream().anyMatch(this::open);
    }
}
