package net.smc.core.cell;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import net.smc.core.cell.TeamState.Child;
import net.smc.core.cell.TeamState.Owned;
import net.smc.core.message.Envelope;
import net.smc.core.message.PolicyRequest;
import net.smc.core.message.Roster;
import net.smc.core.message.Status;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;
import net.smc.core.role.RoleLoadException;
import net.smc.core.transport.Address;

/**
 * Backup commanders: the acting commander replicates the team roster to the first children able to
 * command; a backup prefetches the mission's policies and, when the commander stays silent for its
 * rank's take-over time, leads the team in the next epoch with the roster's members as children.
 * Owns ROSTER.
 */
final class BackupCommander {
    private final TeamContext ctx;
    private final TeamState st;
    private final Seating seating;
    private final TeamCounts counts;
    private final Merge merge;
    /** Whether this backup has asked for every policy file of the mission. */
    private boolean prefetched;
    /** When this acting commander last sent its roster (never: far in the past). */
    private long rosterSentMillis = Long.MIN_VALUE / 2;
    /** Whether the team changed since the last roster, which waits for the next tick. */
    private boolean rosterDue;

    BackupCommander(TeamContext ctx, TeamState st, Seating seating, TeamCounts counts, Merge merge) {
        this.ctx = ctx;
        this.st = st;
        this.seating = seating;
        this.counts = counts;
        this.merge = merge;
    }

    /**
     * The team changed (a seat accepted, a child failed): an acting commander tells its backups now,
     * or, if a roster went to them less than half a heartbeat period ago, at its next tick
     * ({@link #rosterDue}). Each roster names every member, so one per acceptance would cost a
     * commander seating <i>n</i> children directly (the centralised scheme) some <i>n</i>^2 / 2
     * members' entries on its radio while the team forms: 20 MB for a thousand, against the few
     * hundred kilobytes of the assignments themselves.
     */
    void rosterChanged() {
        if (!st.acting) {
            return;
        }
        if (ctx.clock().nowMillis() - rosterSentMillis >= ctx.timing().comTimeoutMillis() / 2) {
            sendRoster();
        } else {
            rosterDue = true;
        }
    }

    /** Whether a change of the team waits to be sent to the backups at this tick. */
    boolean rosterDue() {
        return rosterDue;
    }

    /** Replicates the team roster to the backups: the first children able to command, by identity. */
    void sendRoster() {
        if (!st.acting || ctx.timing().backups() == 0) {
            return;
        }
        MissionRole cdr = ctx.slots().role(Mission.COMMANDER);
        List<Child> able = st.children.values().stream()
                .filter(c -> !c.seats.isEmpty() && c.description != null && cdr.requirement().isMetBy(c.description))
                .sorted(Comparator.comparing((Child c) -> ctx.slots().sequence(c.seats.get(0))))
                .limit(ctx.timing().backups()).toList();
        if (able.isEmpty()) {
            return;
        }
        List<Roster.Entry> members = new ArrayList<>();
        for (Child c : st.children.values()) {
            for (Seat s : c.seats) {
                if (members.size() < Roster.MAX_MEMBERS && c.address != null) {
                    members.add(new Roster.Entry(c.vehicle, c.address.toString(), s.role(), s.slot()));
                }
            }
        }
        Roster r = new Roster(ctx.missionId(), st.epoch, able.stream().map(c -> c.vehicle).toList(), members);
        for (Child b : able) {
            ctx.send(b.address, r);
        }
        rosterSentMillis = ctx.clock().nowMillis();
        rosterDue = false;
    }

    void onRoster(Envelope env, Roster r) {
        if (st.parent == null || !st.parent.vehicle().equals(env.sender()) || !env.sender().equals(st.commander)
                || !r.mission().equals(ctx.missionId())) {
            return;
        }
        st.roster = r;
        st.backupRank = r.backups().indexOf(ctx.self());
        if (st.backupRank >= 0 && !prefetched) {
            prefetched = true;
            for (String uri : ctx.allPolicyUris()) {
                if (ctx.store().get(uri, PolicyStore.ANY_VERSION).isEmpty()) {
                    ctx.send(st.parent.address(), new PolicyRequest(uri, PolicyStore.ANY_VERSION));
                }
            }
        }
    }

    /** The commander went silent: this backup leads the team in the next epoch. */
    void takeOver() {
        for (String uri : ctx.allPolicyUris()) {
            if (ctx.store().get(uri, PolicyStore.ANY_VERSION).isEmpty()) {
                ctx.fromRepository(uri);
            }
        }
        if (!ctx.policiesHeld(Mission.COMMANDER)) {
            ctx.emit(CellEvent.Kind.REJECTED, "cannot take over: the commander's policies are not all here");
            st.backupRank = -1;
            return;
        }
        Roster r = st.roster;
        String old = st.commander;
        try {
            ctx.host().loadRole(Mission.COMMANDER, ctx.store());
        } catch (RoleLoadException e) {
            ctx.emit(CellEvent.Kind.REJECTED, "cannot take over: " + e.getMessage());
            st.backupRank = -1;
            return;
        }
        Set<String> formerChildren = new LinkedHashSet<>(st.children.keySet());
        for (Seat s : List.copyOf(st.seats)) {
            seating.dropOwnSeat(s, "takes over as commander");
        }
        st.seats.clear();
        st.seats.add(Slots.commanderSeat());
        st.identity = ctx.identityOf(Slots.commanderSeat());
        st.acting = true;
        st.parent = null;
        st.ancestors = List.of();
        st.commander = ctx.self();
        st.epoch = r.epoch() + 1;
        st.backupRank = -1;
        st.roster = null;
        st.children.clear();
        st.owned.clear();
        st.linksChanged();
        seating.recomputeOwnership();
        long now = ctx.clock().nowMillis();
        for (Roster.Entry e : r.members()) {
            if (e.vehicle().equals(ctx.self()) || e.vehicle().equals(old) || formerChildren.contains(e.vehicle())) {
                continue; // this cell's own children were just let go; the roster's word on them is stale
            }
            Seat seat = new Seat(e.role(), e.slot());
            Owned o = st.owned.get(seat);
            if (o == null) {
                continue;
            }
            Address address;
            try {
                address = Address.parse(e.address());
            } catch (IllegalArgumentException bad) {
                continue;
            }
            ctx.comm().learnAddress(e.vehicle(), address);
            Child c = st.children.computeIfAbsent(e.vehicle(), Child::new);
            c.address = address;
            c.lastHeard = now;
            c.consistent = false; // the roster may be stale: trust its seats once its own report agrees
            List<Seat> held = new ArrayList<>(c.seats);
            held.add(seat);
            c.seats = List.copyOf(held);
            st.linksChanged();
            o.holder = e.vehicle();
        }
        ctx.emit(CellEvent.Kind.TOOK_OVER, "commander " + old + " silent; leads epoch " + st.epoch + " with children "
                + st.children.keySet());

        for (Child c : st.children.values()) {
            ctx.send(c.address, new Status(ctx.missionId(), st.identity, ctx.self(), st.epoch, counts.teamSize()));
        }
        merge.discover();
        counts.updateMissionState();
    }
}
