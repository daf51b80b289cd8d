package net.smc.core.cell;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import net.smc.core.cell.TeamState.Child;
import net.smc.core.cell.TeamState.Owned;
import net.smc.core.message.Leave;

/**
 * This cell's seats and the seats it owns: giving one up, giving up everything (telling children and
 * remembering them as abandoned), re-deriving ownership from the seats held, vacating a child's seats.
 */
final class Seating {
    private final TeamContext ctx;
    private final TeamState st;

    Seating(TeamContext ctx, TeamState st) {
        this.ctx = ctx;
        this.st = st;

    }

    /** Gives up one of this cell's seats (and the role, unless another seat needs it). */
    void dropOwnSeat(Seat seat, String why) {
        if (!st.seats.remove(seat)) {
            return;
        }
        st.linksChanged();
        ctx.host().withdrawRole(seat.role());
        Owned mine = st.owned.get(seat);
        if (mine != null && ctx.self().equals(mine.holder)) {
            mine.holder = null;
        }
        ctx.emit(CellEvent.Kind.RELEASED, seat + ": " + why);
        recomputeOwnership();
    }

    /** Gives up every seat and child; becomes a free vehicle. */
    void dropEverything(String why) {
        long until = ctx.clock().nowMillis() + ctx.timing().orphanMillis();
        for (Child c : st.children.values()) {
            if (c.address != null && !c.seats.isEmpty()) {
                ctx.send(c.address, new Leave(why));
            }
            st.abandoned.put(c.vehicle, until);
        }
        st.owned.values().stream().filter(o -> o.pendingFor != null).forEach(o -> st.abandoned.put(o.pendingFor, until));
        st.children.clear();
        st.owned.clear();
        st.capabilityRequests.clear();
        st.deferredAsks.clear();
        for (Seat s : List.copyOf(st.seats)) {
            ctx.host().withdrawRole(s.role());
            ctx.emit(CellEvent.Kind.RELEASED, s + ": " + why);
        }
        st.seats.clear();
        st.parent = null;
        st.linksChanged();
        st.ancestors = List.of();
        st.identity = null;
        st.backupRank = -1;
        st.roster = null;
        st.incoming = null;
        st.missionState = null;
        if (!st.acting) {
            st.commander = null;
        }
    }

    /** Re-derives the seats this cell owns from the seats it holds, keeping what it knew of them. */
    void recomputeOwnership() {
        Set<Seat> now = new LinkedHashSet<>();
        for (Seat s : st.seats) {
            now.addAll(ctx.slots().ownedBy(s));
        }
        st.owned.keySet().retainAll(now);
        for (Seat s : now) {
            st.owned.computeIfAbsent(s, k -> new Owned());
        }
        for (Map.Entry<Seat, Owned> e : st.owned.entrySet()) {
            boolean mine = st.seats.contains(e.getKey());
            if (mine) {
                e.getValue().holder = ctx.self();
            } else if (ctx.self().equals(e.getValue().holder)) {
                e.getValue().holder = null;
            }
        }
        for (Child c : List.copyOf(st.children.values())) {
            List<Seat> kept = c.seats.stream().filter(st.owned::containsKey).toList();
            if (kept.size() != c.seats.size()) {
                c.seats = kept;
                st.linksChanged();
                if (kept.isEmpty()) {
                    st.children.remove(c.vehicle);
                    if (c.address != null) {
                        ctx.send(c.address, new Leave("'" + ctx.self() + "' no longer manages its seats"));
                    }
                }
            }
        }
    }

    /** Frees the seats this cell's table gives a child it no longer has. */
    void vacate(Child child) {
        for (Seat s : child.seats) {
            Owned o = st.owned.get(s);
            if (o != null && child.vehicle.equals(o.holder)) {
                o.holder = null;
            }
        }
    }
}
