package net.smc.core.cell;

import net.smc.core.message.Discovery;

/**
 * Merging of partitioned teams: an acting commander beacons its discovery (the same message that
 * recruits), and of two commanders that meet, the one of the lower epoch (then the higher vehicle
 * id) steps down and frees its vehicles, which the other then recruits.
 */
final class Merge {
    private final TeamContext ctx;
    private final TeamState st;
    private final Seating seating;

    Merge(TeamContext ctx, TeamState st, Seating seating) {
        this.ctx = ctx;
        this.st = st;
        this.seating = seating;
    }

    /** Broadcasts a discovery naming this cell's primary role. */
    void discover() {
        Seat primary = st.seats.get(0);
        long id = ctx.comm().broadcast(new Discovery(ctx.missionId(), primary.role(), ctx.slots().level(primary.role()), st.epoch));
        st.discoveries.sent(id, ctx.clock().nowMillis() + ctx.comm().backlogMillis());
    }

    /** Two acting commanders met: the one with the higher epoch, then the lower vehicle id, stays. */
    void meetCommander(String other, long otherEpoch) {
        boolean otherWins = otherEpoch > st.epoch || (otherEpoch == st.epoch && other.compareTo(ctx.self()) < 0);
        if (!otherWins) {
            return;
        }
        ctx.emit(CellEvent.Kind.STEPPED_DOWN, "meets commander " + other + " of epoch " + otherEpoch + " (own epoch "
                + st.epoch + ") and steps down");
        st.acting = false;
        st.linksChanged();
        seating.dropEverything("commander " + ctx.self() + " stepped down for " + other);
        st.commander = null;
        st.epoch = 0;
    }
}
