package net.smc.core.cell;

import java.util.List;
import java.util.Map;
import java.util.Optional;

import net.smc.core.cell.TeamState.Child;
import net.smc.core.cell.TeamState.Owned;
import net.smc.core.message.AssignmentResponse;
import net.smc.core.message.Envelope;
import net.smc.core.message.Invocation;
import net.smc.core.message.Leave;
import net.smc.core.transport.Address;

/**
 * A manager's side of the answers to its role assignments (part of {@link Recruiter}): an acceptance
 * makes the vehicle a child holding the seat; a refusal, or no answer within the reservation, opens
 * the seat again and looks for another vehicle at once; an acceptance of a seat no longer reserved
 * for the vehicle is revoked. A refusal of a capability request that is still out (the vehicle took
 * a seat from another manager since it answered discovery) lets this cell look again too.
 */
final class AssignmentAnswers {
    private final TeamContext ctx;
    private final TeamState st;
    private final TeamCounts counts;
    private final BackupCommander backup;
    /** Looks for another vehicle for a seat open again: the vehicles waiting their turn, those heard lately, else discovery. */
    private final Runnable lookAgain;

    AssignmentAnswers(TeamContext ctx, TeamState st, TeamCounts counts, BackupCommander backup, Runnable lookAgain) {
        this.ctx = ctx;
        this.st = st;
        this.counts = counts;
        this.backup = backup;
        this.lookAgain = lookAgain;
    }

    void onAssignmentResponse(Envelope env, AssignmentResponse r) {
        String vehicle = env.sender();
        Optional<Seat> seat = st.owned.entrySet().stream()
                .filter(e -> vehicle.equals(e.getValue().pendingFor) && e.getKey().role().equals(r.role()))
                .map(Map.Entry::getKey).findFirst();
        if (seat.isEmpty() && !r.accepted() && st.capabilityRequests.remove(vehicle) != null) {
            // The vehicle declined a capability request: it took a seat from another manager since it
            // answered discovery. The request no longer holds rediscovery back; look again now.
            st.forgetAnswer(vehicle);
            lookAgain.run();
            return;
        }
        if (seat.isEmpty()) {
            Child child = st.children.get(vehicle);
            boolean known = child != null && child.seats.stream().anyMatch(s -> s.role().equals(r.role()));
            if (r.accepted() && !known) {
                revoke(vehicle, r.role());
            }
            return; // known: its heartbeat already told us it took the seat
        }
        if (!r.accepted()) {
            assignmentFailed(vehicle, seat.get(), "refused: " + r.reason());
            return;
        }
        accepted(vehicle, seat.get());
        Child c = st.children.get(vehicle);
        if (c != null) {
            c.confirmedBy.put(seat.get(), env.id());
        }
    }

    /**
     * A vehicle took a seat this cell no longer reserves for it (the reservation expired): it must
     * give the role back, or it would hold a seat that may have gone to another.
     */
    private void revoke(String vehicle, String role) {
        Child child = st.children.get(vehicle);
        Optional<Address> to = ctx.address(vehicle);
        if (to.isEmpty()) {
            return;
        }
        ctx.emit(CellEvent.Kind.REJECTED, vehicle + " took " + role + " after its reservation expired; revoked");
        if (child != null && !child.seats.isEmpty()) {
            ctx.comm().send(to.get(), new Invocation(role, "release", List.of()));
        } else {
            ctx.send(to.get(), new Leave("'" + ctx.self() + "' no longer holds a seat of '" + role + "' for '" + vehicle + "'"));
        }
    }

    /** The vehicle took the seat: it is now a child holding it. */
    void accepted(String vehicle, Seat seatTaken) {
        Optional<Seat> seat = Optional.of(seatTaken);
        Owned o = st.owned.get(seat.get());
        o.pendingFor = null;
        o.holder = vehicle;
        Child child = st.children.computeIfAbsent(vehicle, Child::new);
        child.address = ctx.address(vehicle).orElse(child.address);
        child.lastHeard = ctx.clock().nowMillis();
        List<Seat> before = child.seats;
        child.seats = ctx.slots().afterAssign(before, seat.get()).stream().filter(st.owned::containsKey).toList();
        st.linksChanged();
        for (Seat dropped : before) {
            if (!child.seats.contains(dropped) && st.owned.containsKey(dropped) && vehicle.equals(st.owned.get(dropped).holder)) {
                st.owned.get(dropped).holder = null;
            }
        }
        st.handover.remove(seat.get().role());
        st.forgetAnswer(vehicle);
        ctx.emit(CellEvent.Kind.ASSIGNED, seat.get() + " to " + vehicle + " (now holds " + child.seats + ")");
        backup.rosterChanged();
        counts.updateMissionState();
    }

    void assignmentFailed(String vehicle, Seat seat, String why) {
        Owned o = st.owned.get(seat);
        if (o == null || !vehicle.equals(o.pendingFor)) {
            return;
        }
        o.pendingFor = null;
        Child child = st.children.get(vehicle);
        if (child != null && child.seats.isEmpty()) {
            st.children.remove(vehicle);
            st.linksChanged();
        }
        st.forgetAnswer(vehicle); // it refused, or fell silent: what it answered no longer holds
        ctx.emit(CellEvent.Kind.ASSIGNMENT_FAILED, seat + " to " + vehicle + ": " + why);
        // The seat is open again: look for another vehicle now (one taken by a neighbouring manager,
        // say), not at the next tick.
        lookAgain.run();
    }
}
