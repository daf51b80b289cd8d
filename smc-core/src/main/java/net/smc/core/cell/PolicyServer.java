package net.smc.core.cell;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import net.smc.core.cell.TeamState.ParkedRequest;
import net.smc.core.message.Envelope;
import net.smc.core.message.PolicyReply;
import net.smc.core.message.PolicyRequest;
import net.smc.core.message.WireFormat;
import net.smc.core.transport.Address;
import net.smc.core.wire.StrictUtf8;

/**
 * A manager's policy files for the vehicles below it (part of {@link Recruiter}): answers their
 * requests, sends a new assignee its files right behind the assignment, and holds back a request
 * or a file to send that this cell is still fetching itself until it arrives.
 */
final class PolicyServer {
    private final TeamContext ctx;
    private final TeamState st;

    PolicyServer(TeamContext ctx, TeamState st) {
        this.ctx = ctx;
        this.st = st;
    }

    /**
     * Sends a vehicle just assigned {@code role} policy files right behind the assignment, as
     * replies to it ({@link TeamContext#policiesWithAssignment}): first the role's own (its
     * role-missions and authorisations: the vehicle starts the role when they are in), then those
     * of the roles it manages directly, which it sends on to its own children. Asking for them
     * would add a round trip to every level of the management tree, and a manager that fetched its
     * children's files only once its role had started would hold its first child's role up until
     * they came. The files of the roles further down, needed a level later, the vehicle fetches
     * once its role has started, so that a manager assigning several roles at once sends their
     * own files before the deeper ones. A file still on its way to this cell goes when it arrives.
     * The vehicle asks for any that has not come within a heartbeat period (Assignee), so a file
     * this cell could not send still reaches it; one of the same role this vehicle holds from this
     * cell it has already.
     */
    void sendWithAssignment(Address to, String role, long assignmentId) {
        for (String uri : ctx.policiesWithAssignment(role)) {
            Optional<PolicyStore.Entry> entry = held(uri, PolicyStore.ANY_VERSION);
            if (entry.isPresent()) {
                reply(assignmentId, uri, entry.get()).ifPresent(reply -> ctx.comm().send(to, reply));
            } else if (onItsWay(uri)) {
                st.parkedPolicyRequests.computeIfAbsent(uri, u -> new ArrayList<>())
                        .add(new ParkedRequest(to, assignmentId, PolicyStore.ANY_VERSION, ctx.clock().nowMillis()));
            }
        }
    }

    /** The file this cell can serve: from its store, or (as acting or backup commander) from its repository. */
    private Optional<PolicyStore.Entry> held(String uri, int version) {
        Optional<PolicyStore.Entry> entry = ctx.store().get(uri, version);
        if (entry.isEmpty() && (st.acting || st.backupRank >= 0)) {
            entry = ctx.fromRepository(uri).filter(e -> version == PolicyStore.ANY_VERSION || e.version() == version);
        }
        return entry;
    }

    void onPolicyRequest(Envelope env, PolicyRequest r) {
        Optional<PolicyStore.Entry> entry = held(r.uri(), r.version());
        Optional<Address> back = ctx.address(env.sender());
        if (entry.isEmpty() && back.isPresent() && onItsWay(r.uri())) {
            st.parkedPolicyRequests.computeIfAbsent(r.uri(), u -> new ArrayList<>())
                    .add(new ParkedRequest(back.get(), env.id(), r.version(), ctx.clock().nowMillis()));
            return; // answered when the file arrives (policyArrived)
        }
        if (entry.isEmpty() || back.isEmpty()) {
            ctx.reject(env, "policy " + r.uri() + " version " + r.version() + " is not held here");
            return;
        }
        Optional<PolicyReply> reply = reply(env.id(), r.uri(), entry.get());
        if (reply.isEmpty()) {
            ctx.reject(env, "policy " + r.uri() + " is " + StrictUtf8.length(entry.get().text())
                    + " bytes of text; a policy reply carries at most " + WireFormat.MAX_POLICY_TEXT);
            return;
        }
        ctx.comm().send(back.get(), reply.get());
    }

    /**
     * The reply carrying {@code entry}, or empty when its text is longer than a policy reply may
     * carry. A mission's loader refuses such files, but a commander reads its repository while
     * the mission runs, and a file changed meanwhile must not throw out of the cell's handler: it
     * is not sent, and the vehicle that needs it asks again and is refused, named.
     */
    private static Optional<PolicyReply> reply(long inReplyTo, String uri, PolicyStore.Entry entry) {
        if (StrictUtf8.length(entry.text()) > WireFormat.MAX_POLICY_TEXT) {
            return Optional.empty();
        }
        return Optional.of(new PolicyReply(inReplyTo, uri, entry.version(), entry.text()));
    }

    /**
     * Whether a policy file this cell does not hold is on its way to it: a file of the roles below
     * one it holds, which its manager sends behind the assignment or it fetches after taking the role.
     */
    private boolean onItsWay(String uri) {
        return st.parent != null && st.seats.stream().anyMatch(s -> ctx.subtreePolicyUris(s.role()).contains(uri));
    }

    /** A policy file arrived: answers the children's requests, and sends the assignees' files, that waited for it. */
    void policyArrived(String uri) {
        List<ParkedRequest> parked = st.parkedPolicyRequests.get(uri);
        if (parked == null) {
            return;
        }
        parked.removeIf(p -> {
            Optional<PolicyStore.Entry> entry = ctx.store().get(uri, p.version());
            entry.flatMap(e -> reply(p.envelopeId(), uri, e)).ifPresent(reply -> ctx.comm().send(p.from(), reply));
            return entry.isPresent();
        });
        if (parked.isEmpty()) {
            st.parkedPolicyRequests.remove(uri);
        }
    }

    /** Drops the requests and files to send that waited longer than the failure timeout. */
    void expire(long now) {
        if (st.parkedPolicyRequests.isEmpty()) {
            return; // the usual case once a team has formed (see Recruiter.dropIf)
        }
        st.parkedPolicyRequests.values().removeIf(parked -> {
            parked.removeIf(p -> now - p.atMillis() > ctx.timing().failureTimeoutMillis());
            return parked.isEmpty();
        });
    }
}
