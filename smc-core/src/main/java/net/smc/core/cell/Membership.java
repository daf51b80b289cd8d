package net.smc.core.cell;

import java.util.List;

import net.smc.core.cell.TeamState.Child;
import net.smc.core.cell.TeamState.Parent;
import net.smc.core.message.Echo;
import net.smc.core.message.Envelope;
import net.smc.core.message.Heartbeat;
import net.smc.core.message.Leave;
import net.smc.core.message.SubtreeReport;
import net.smc.core.message.Status;

/**
 * Membership as a child: heartbeats and subtree reports to the parent, the lease its statuses and echoes renew
 * (SUSPENDED when it lapses, ORPHANED when the parent is lost), adoption by a backup that took over,
 * and Leaves from parent or children. Owns STATUS, ECHO and LEAVE.
 */
final class Membership {
    private final TeamContext ctx;
    private final TeamState st;
    /**
     * Heartbeats between unchanged subtree reports: a report that changed goes at once, so the
     * unchanged one only repairs what was lost (with the repeats below) and dates the parent's copy.
     */
    static final int REPORT_TICKS = 16;
    /**
     * Heartbeats after a changed report that send it again (unless it changed once more): a change
     * reaches the parent unless this many plus one datagrams in a row are lost, though the
     * unchanged report is sent only every {@link #REPORT_TICKS} heartbeats.
     */
    static final int REPORT_REPEATS = 2;

    private final Seating seating;
    private final TeamCounts counts;
    private final BackupCommander backup;
    private final Reports reports;
    /** Send times of recent heartbeats, by their {@linkplain Echo#tagOf tag}, to date the parent's echoes. */
    private final HeartbeatTimes heartbeatSentAt = new HeartbeatTimes();
    /** Heartbeats until an unchanged subtree report is sent again. */
    private int reportCountdown;
    /** Copies of the latest changed report still to send, one a heartbeat. */
    private int reportRepeats;
    /**
     * Whether the parent's latest answer echoed no heartbeat: it does not vouch for the seats this
     * cell holds (its table disagrees, or it adopted this cell from a roster) until a subtree report
     * of them agrees with its table. While so, the report goes with every heartbeat: an unchanged
     * report every {@link #REPORT_TICKS} heartbeats would leave a suspended child waiting as long
     * for each try, and on a lossy link several tries in a row may be lost.
     */
    private boolean unconfirmed;
    private List<Object> lastReport = List.of();

    Membership(TeamContext ctx, TeamState st, Seating seating, TeamCounts counts, BackupCommander backup, Reports reports) {
        this.ctx = ctx;
        this.st = st;
        this.seating = seating;
        this.counts = counts;
        this.backup = backup;
        this.reports = reports;
    }

    void asChild(long now) {
        if (st.parent == null) {
            return;
        }
        if (st.seats.isEmpty()) {
            ctx.send(st.parent.address(), new Leave("'" + ctx.self() + "' holds no role any more"));
            seating.dropEverything("holds no role any more");
            return;
        }
        long silent = now - st.lastStatusMillis;
        if (st.backupRank >= 0 && st.commander != null && st.parent.vehicle().equals(st.commander)
                && silent > ctx.timing().takeoverMillis(st.backupRank)) {
            backup.takeOver();
            return;
        }
        if (silent > ctx.timing().orphanMillis()) {
            ctx.emit(CellEvent.Kind.ORPHANED, "nothing from parent " + st.parent.vehicle() + " for " + silent + " ms; drops "
                    + st.seats);
            seating.dropEverything("parent " + st.parent.vehicle() + " is lost");
            return;
        }
        if (st.suspended() && !st.lapseNoted) {
            st.lapseNoted = true;
            ctx.emit(CellEvent.Kind.SUSPENDED, "lease from " + st.parent.vehicle() + " ran out " + (now - st.leaseUntilMillis)
                    + " ms ago; last status " + silent + " ms ago");
        }
        // The heartbeat's state field carries the slot of the primary seat, so the parent knows the exact seat.
        long held = st.parent.vehicle().equals(st.statusVersionFrom) ? st.statusVersionHeld : 0;
        long id = ctx.comm().send(st.parent.address(), new Heartbeat(st.seats.get(0).role(), st.epoch, st.seats.get(0).slot(), held));
        heartbeatSentAt.put(Echo.tagOf(id), now);
        List<Object> report = reports.reportValues();
        boolean send;
        if (!report.equals(lastReport)) {
            reportRepeats = REPORT_REPEATS;
            send = true;
        } else if (reportRepeats > 0) {
            reportRepeats--;
            send = true;
        } else if (unconfirmed || st.suspended()) {
            send = true;
        } else {
            send = --reportCountdown <= 0;
        }
        if (send) {
            reportCountdown = REPORT_TICKS;
            lastReport = report;
            ctx.send(st.parent.address(), new SubtreeReport(st.seats.get(0).role(), report));
        }
    }

    void onStatus(Envelope env, Status s) {
        if (!s.mission().equals(ctx.missionId())) {
            return;
        }
        String from = env.sender();
        if (st.parent != null && st.parent.vehicle().equals(from)) {
            renew(s.echo() == 0 ? 0 : Echo.tagOf(s.echo()));
            st.statusVersionHeld = s.version();
            st.statusVersionFrom = from;
            st.epoch = s.epoch();
            st.commander = s.commander();
            st.teamSize = s.teamSize();
            st.ancestors = TeamContext.lineage(from, s.ancestors());
            return;
        }
        // A backup that took over claims the old commander's children.
        if (st.parent != null && st.parent.vehicle().equals(st.commander) && s.commander().equals(from) && s.epoch() > st.epoch) {
            ctx.emit(CellEvent.Kind.ADOPTED, "new commander " + from + " of epoch " + s.epoch() + " replaces " + st.commander);
            st.parent = new Parent(from, ctx.address(from).orElse(st.parent.address()));
            st.ancestors = List.of(from);
            st.commander = from;
            st.epoch = s.epoch();
            st.lastStatusMillis = ctx.clock().nowMillis();
            st.statusVersionHeld = s.version();
            st.statusVersionFrom = from;
            // Seats granted by the old commander count again only once the new one has echoed a heartbeat.
            st.leaseUntilMillis = ctx.clock().nowMillis() - 1;
            st.linksChanged();
            st.backupRank = -1;
            st.roster = null;
            reportCountdown = 0;
            // The new commander's echo confirms only the seat the heartbeat names (the primary one).
            // A further seat the old commander owned may be one the new commander has since given to
            // another vehicle, or one the old commander gave after the takeover (the new commander
            // never heard of it): holding it on the strength of that echo would seat two vehicles.
            // Seats owned by a seat this vehicle keeps stay; the new commander may give the rest again.
            for (Seat seat : st.seats.size() < 2 ? List.<Seat>of() : List.copyOf(st.seats.subList(1, st.seats.size()))) {
                if (!ctx.slots().owner(seat).map(st.seats::contains).orElse(false)) {
                    seating.dropOwnSeat(seat, "adopted by new commander " + from + ", which did not give it");
                }
            }
        }
    }

    /** The parent's answer while this cell holds its current status: the parent is alive, and the lease renewed. */
    void onEcho(Envelope env, Echo e) {
        if (st.parent != null && st.parent.vehicle().equals(env.sender())) {
            renew(e.echo());
        }
    }

    /** The parent was heard; its echo of a heartbeat (by its tag; 0: none) renews the lease from that heartbeat's sending. */
    private void renew(long tag) {
        st.lastStatusMillis = ctx.clock().nowMillis();
        unconfirmed = tag == 0;
        long sentAt = tag == 0 ? HeartbeatTimes.NONE : heartbeatSentAt.sentAt(tag);
        if (sentAt != HeartbeatTimes.NONE && sentAt + ctx.timing().leaseMillis() > st.leaseUntilMillis) {
            st.leaseUntilMillis = sentAt + ctx.timing().leaseMillis();   // a later end only: see TeamState.linkVersion
            st.lapseNoted = false;
        }
    }

    void onLeave(Envelope env, Leave l) {
        String from = env.sender();
        if (st.parent != null && st.parent.vehicle().equals(from)) {
            ctx.emit(CellEvent.Kind.LEFT, "parent " + from + " says: " + l.reason());
            seating.dropEverything("parent " + from + " let go: " + l.reason());
            return;
        }
        Child child = st.children.remove(from);
        if (child != null) {
            st.linksChanged();
            seating.vacate(child);
            ctx.emit(CellEvent.Kind.LEFT, "child " + from + " left (" + l.reason() + "); vacated " + child.seats);
            counts.updateMissionState();
        }
    }
}
