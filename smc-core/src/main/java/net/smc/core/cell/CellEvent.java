package net.smc.core.cell;

/**
 * One decision or observation of a cell, for logs, traces and tests: when (the cell's clock, ms),
 * which vehicle, what kind, and a human-readable detail.
 */
public record CellEvent(long timeMillis, String vehicle, Kind kind, String detail) {

    /** What happened. */
    public enum Kind {
        /** Acting commander from the start. */
        COMMANDING,
        /** Broadcast a discovery. */
        DISCOVERING,
        /** Sent a role assignment to a vehicle. */
        ASSIGNING,
        /** A vehicle accepted a role from this cell. */
        ASSIGNED,
        /** A vehicle refused a role, or the assignment was not delivered. */
        ASSIGNMENT_FAILED,
        /** This cell accepted a role. */
        ACCEPTED,
        /** This cell refused a role. */
        REFUSED,
        /** This cell took a secondary role on its own vehicle. */
        HOSTING,
        /** This cell gave up a role. */
        RELEASED,
        /** A child stopped answering; UAVFailure was raised. */
        FAILURE,
        /** A re-assignment was asked for and decided. */
        REASSIGNING,
        /** The lease from the parent ran out: this cell no longer counts as holding its roles. */
        SUSPENDED,
        /** The parent was lost for good: roles dropped, free again. */
        ORPHANED,
        /** A backup commander took over the team. */
        TOOK_OVER,
        /** Adopted a new parent that took over from the old one. */
        ADOPTED,
        /** An acting commander met a stronger one and stepped down. */
        STEPPED_DOWN,
        /** A vehicle left, or was told to leave. */
        LEFT,
        /** The commander's view of the mission changed state. */
        MISSION_STATE,
        /** Input that was refused (named in the detail). */
        REJECTED,
        /** A role's event was sent towards the roles of other vehicles that subscribe to it. */
        PUBLISHED,
        /** A remote event or invocation passed the receiving role's authorisations and ran here. */
        DELIVERED,
        /** An operation of another vehicle's role was called, or its answer arrived. */
        INVOKED
    }

    @Override
    public String toString() {
        return String.format("%8d %-10s %-17s %s", timeMillis, vehicle, kind, detail);
    }
}
