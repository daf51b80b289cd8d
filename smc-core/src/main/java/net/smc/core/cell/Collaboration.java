package net.smc.core.cell;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import net.smc.core.cell.TeamState.Child;
import net.smc.core.comm.DeliveryListener;
import net.smc.core.comm.FailureReason;
import net.smc.core.message.Envelope;
import net.smc.core.message.Invocation;
import net.smc.core.message.InvocationResult;
import net.smc.core.message.RoleEvent;
import net.smc.core.mission.MissionRole;
import net.smc.core.role.Caller;
import net.smc.core.role.ExternalCallException;
import net.smc.core.transport.Address;

/**
 * Roles across vehicles (the paper's section II-B.2.A): events a role publishes travel to the
 * vehicles whose roles subscribe to them, and operations a role offers are invoked from other
 * vehicles, with the answer coming back. Owns ROLE_EVENT, INVOCATION and INVOCATION_RESULT (a
 * parent's {@code release} goes on to {@link Assignee}).
 *
 * <p>Routing follows the management tree, the only map of the team a cell has: a message goes to
 * the tree neighbours (parent, children) other than the one it came from, to a child only when the
 * subtree that child reports holds a role that wants it (subscribes to the event; is the invoked
 * role). The acting commander's children cover the team, so an event reaches every subscriber of
 * the team and an invocation a holder of its role. Every hop is reliable. A cell holding a
 * subscribing (invoked) role hands it to its Role-Manager's external gateway, whose authorisation
 * policies decide with the caller as subject, {@code root/role/<role>/peers/<caller role>/<caller cell>}.
 * A refusal is answered with a failed INVOCATION_RESULT; an invocation's answer goes to the address
 * the caller gave, else back to the sender.
 */
final class Collaboration {
    private final TeamContext ctx;
    private final TeamState st;
    private final Assignee assignee;
    private final Map<Long, String> pending = new LinkedHashMap<>();
    private long nextCall = 1;

    Collaboration(TeamContext ctx, TeamState st, Assignee assignee) {
        this.ctx = ctx;
        this.st = st;
        this.assignee = assignee;
    }

    /** The next call number, shared by every request of this cell whose answer is a {@code remoteResult}. */
    long nextCall() {
        return nextCall++;
    }

    /** Publishes an event a role of this cell raised; returns how many neighbours it was sent to. */
    int publish(String role, String event, List<Object> values) {
        RoleEvent e = new RoleEvent(role, event, values, ctx.self());
        int sent = forward(e, null);
        ctx.emit(CellEvent.Kind.PUBLISHED, role + " " + event + " " + values + " to " + sent + " neighbour(s)");
        return sent;
    }

    void onRoleEvent(Envelope env, RoleEvent e) {
        String origin = e.originOr(env.sender());
        if (origin.equals(ctx.self())) {
            return;
        }
        String role = heldRole(r -> r.interfaces().subscribes().contains(e.event()));
        if (role != null) {
            try {
                ctx.host().deliver(new Caller(origin, e.role()), role, e.event(), e.values());
                ctx.emit(CellEvent.Kind.DELIVERED, e.event() + " of " + e.role() + " on " + origin + " to " + role);
            } catch (ExternalCallException | IllegalArgumentException refused) {
                refuse(env, e.event() + " of " + e.role() + " on " + origin, refused.getMessage());
            }
        }
        forward(new RoleEvent(e.role(), e.event(), e.values(), origin), env.sender());
    }

    /**
     * Invokes {@code operation} of {@code role} on whichever vehicle holds it, as {@code callerRole};
     * the answer is raised as {@code remoteResult}.
     *
     * @return the call's number, the {@code call} of its {@code remoteResult}
     */
    long invoke(String callerRole, String role, String operation, List<Object> args) {
        long call = nextCall++;
        Invocation i = new Invocation(role, operation, args, callerRole, call, ctx.self(),
                ctx.comm().localAddress().toString());
        Optional<Address> next = route(role, null);
        if (next.isEmpty()) {
            ctx.host().raise("remoteResult", "remoteResult", call, false, null,
                    "no vehicle holding role '" + role + "' is known to '" + ctx.self() + "'");
            return call;
        }
        pending.put(call, role + " " + operation);
        ctx.emit(CellEvent.Kind.INVOKED, "call " + call + ": " + role + " " + operation + " " + args);
        ctx.comm().send(next.get(), i, new DeliveryListener() {
            @Override
            public void failed(long id, FailureReason reason) {
                if (pending.remove(call) != null) {
                    ctx.host().raise("remoteResult", "remoteResult", call, false, null,
                            "call of " + role + " " + operation + " was not delivered: " + reason);
                }
            }
        });
        return call;
    }

    void onInvocation(Envelope env, Invocation i) {
        if (i.call() == 0) {
            assignee.onInvocation(env, i);
            return;
        }
        String origin = i.originOr(env.sender());
        boolean holds = st.seats.stream().anyMatch(s -> s.role().equals(i.role())) && !st.suspended();
        if (!holds) {
            Optional<Address> next = route(i.role(), env.sender());
            if (next.isPresent()) {
                ctx.comm().send(next.get(), new Invocation(i.role(), i.operation(), i.args(), i.caller(), i.call(), origin,
                        i.reply()));
                return;
            }
            answer(env, i, InvocationResult.failed(i.call(), TeamContext.truncate("no vehicle holding role '" + i.role()
                    + "' is reachable from '" + ctx.self() + "'")));
            return;
        }
        if (i.caller().isEmpty()) {
            answer(env, i, InvocationResult.failed(i.call(), "an invocation of another role names the caller's role"));
            return;
        }
        InvocationResult result;
        try {
            Object value = ctx.host().invoke(new Caller(origin, i.caller()), i.role(), i.operation(), i.args());
            result = InvocationResult.ok(i.call(), WireValues.of(value));
            ctx.emit(CellEvent.Kind.DELIVERED, i.operation() + " of " + i.role() + " by " + i.caller() + " on " + origin);
        } catch (ExternalCallException | IllegalArgumentException refused) {
            ctx.emit(CellEvent.Kind.REJECTED, i.operation() + " of " + i.role() + " by " + i.caller() + " on " + origin
                    + ": " + refused.getMessage());
            result = InvocationResult.failed(i.call(), TeamContext.truncate(refused.getMessage()));
        }
        answer(env, i, result);
    }

    void onInvocationResult(Envelope env, InvocationResult r) {
        String what = pending.remove(r.inReplyTo());
        if (what == null && !r.ok()) {
            ctx.emit(CellEvent.Kind.REJECTED, "error answer from " + env.sender() + " to message " + r.inReplyTo() + ": "
                    + r.error());
            return;
        }
        if (what == null) {
            ctx.reject(env, "result of call " + r.inReplyTo() + ", which this cell is not waiting for"
                    + (r.ok() ? "" : " (error: " + r.error() + ")"));
            return;
        }
        ctx.emit(CellEvent.Kind.INVOKED, "call " + r.inReplyTo() + " (" + what + ") answered by " + env.sender() + ": "
                + (r.ok() ? r.value() : "error " + r.error()));
        ctx.host().raise("remoteResult", "remoteResult", r.inReplyTo(), r.ok(), r.value(), r.error());
    }

    private void answer(Envelope env, Invocation i, InvocationResult result) {
        Optional<Address> to = Optional.empty();
        if (!i.reply().isEmpty()) {
            try {
                to = Optional.of(Address.parse(i.reply()));
            } catch (IllegalArgumentException bad) {
                ctx.reject(env, "reply address '" + i.reply() + "' is not host:port; answering the sender");
            }
        }
        if (to.isEmpty()) {
            to = ctx.address(env.sender());
        }
        to.ifPresent(a -> ctx.comm().send(a, result));
    }

    private void refuse(Envelope env, String what, String why) {
        String text = TeamContext.truncate(what + " refused by '" + ctx.self() + "': " + why);
        ctx.emit(CellEvent.Kind.REJECTED, text);
        ctx.address(env.sender()).ifPresent(a -> ctx.comm().send(a, InvocationResult.failed(env.id(), text)));
    }

    /** Sends {@code e} to every tree neighbour but {@code from} that may lead to a subscriber. */
    private int forward(RoleEvent e, String from) {
        Set<String> wanting = wanting(r -> r.interfaces().subscribes().contains(e.event()));
        if (wanting.isEmpty()) {
            return 0;
        }
        int sent = 0;
        for (Address to : neighbours(wanting, from, true)) {
            ctx.comm().send(to, e);
            sent++;
        }
        return sent;
    }

    /** The next hop towards a holder of {@code role}: a child whose subtree holds it, else the parent. */
    private Optional<Address> route(String role, String from) {
        List<Address> hops = neighbours(Set.of(role), from, false);
        return hops.isEmpty() ? Optional.empty() : Optional.of(hops.get(0));
    }

    private List<Address> neighbours(Set<String> roles, String from, boolean all) {
        List<Address> out = new ArrayList<>();
        for (Child c : st.children.values()) {
            if (c.vehicle.equals(from) || c.address == null) {
                continue;
            }
            Set<String> below = new LinkedHashSet<>();
            c.seats.forEach(s -> below.add(s.role()));
            if (c.subtree != null) {
                c.subtree.forEach((r, n) -> {
                    if (n > 0) {
                        below.add(r);
                    }
                });
            }
            if (below.stream().anyMatch(roles::contains)) {
                out.add(c.address);
                if (!all) {
                    return out;
                }
            }
        }
        if (st.parent != null && !st.acting && !st.parent.vehicle().equals(from)) {
            out.add(st.parent.address());
        }
        return out;
    }

    /** The first role this cell holds that {@code test} accepts, or null. */
    private String heldRole(java.util.function.Predicate<MissionRole> test) {
        for (Seat s : st.seats) {
            if (ctx.slots().mission().role(s.role()).filter(test).isPresent()) {
                return s.role();
            }
        }
        return null;
    }

    private Set<String> wanting(java.util.function.Predicate<MissionRole> test) {
        Set<String> roles = new LinkedHashSet<>();
        for (MissionRole r : ctx.slots().mission().roles()) {
            if (test.test(r)) {
                roles.add(r.name());
            }
        }
        return roles;
    }
}
