package net.smc.core.cell;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.LongSupplier;

import net.smc.core.comm.DeliveryListener;
import net.smc.core.comm.FailureReason;
import net.smc.core.message.CellRequest;
import net.smc.core.message.Envelope;
import net.smc.core.message.InvocationResult;
import net.smc.core.role.Caller;
import net.smc.core.role.ExternalCallException;
import net.smc.core.transport.Address;
import net.smc.policy.api.PonderError;

/**
 * Requests of standard objects to another cell of the team, addressed by vehicle
 * ({@code EventForwarder forwardTo: "/team/a1/..."}, {@code PonderTalk create: "/team/a1"}). Owns
 * CELL_REQUEST; its answers are INVOCATION_RESULTs, which {@link Collaboration} hands here when they
 * answer a request of this class.
 *
 * <p>Routing: straight to the addressed cell when its address is known (it has been heard from,
 * authenticated), else up the management tree to the parent, which does the same; the acting
 * commander, knowing no way on, answers with an error. The receiving cell runs the request with
 * the caller's role as subject ({@code root/role/<role>/peers/<caller role>/<caller cell>}, in the
 * receiving role the path names, else its first role), so its authorisation policies decide; a
 * refusal or a failure is a failed answer, raised at the caller as {@code remoteResult} and, for a
 * forwarded event, also reported there as an error.
 */
final class CellRequests {
    private final TeamContext ctx;
    private final TeamState st;
    private final LongSupplier callNumbers;
    private final Map<Long, CellRequest> pending = new LinkedHashMap<>();

    CellRequests(TeamContext ctx, TeamState st, LongSupplier callNumbers) {
        this.ctx = ctx;
        this.st = st;
        this.callNumbers = callNumbers;
    }

    /** Sends a request made of its parts and the next call number; returns the call number. */
    long send(CellRequest.Kind kind, String cell, String path, String selector, String event, Object value) {
        if (st.seats.isEmpty()) {
            throw new PonderError("this cell holds no role yet, so it cannot reach /team/" + cell);
        }
        long call = callNumbers.getAsLong();
        CellRequest r;
        try {
            r = new CellRequest(kind, cell, path, selector, event, List.of(value), st.seats.get(0).role(), call, "",
                    ctx.comm().localAddress().toString());
        } catch (IllegalArgumentException bad) {
            throw new PonderError("cannot send to /team/" + cell + ": " + bad.getMessage());
        }
        if (cell.equals(ctx.self())) {
            throw new PonderError("/team/" + cell + " is this cell itself; address its objects directly");
        }
        Optional<Address> next = route(cell, null);
        if (next.isEmpty()) {
            answered(r, InvocationResult.failed(call, "no way to cell '" + cell + "' is known to '" + ctx.self() + "'"));
            return call;
        }
        pending.put(call, r);
        ctx.emit(CellEvent.Kind.INVOKED, "call " + call + ": " + describe(r));
        ctx.comm().send(next.get(), r, new DeliveryListener() {
            @Override
            public void failed(long id, FailureReason reason) {
                CellRequest lost = pending.remove(call);
                if (lost != null) {
                    answered(lost, InvocationResult.failed(call, TeamContext.truncate(describe(lost)
                            + " was not delivered: " + reason)));
                }
            }
        });
        return call;
    }

    void onCellRequest(Envelope env, CellRequest r) {
        String origin = r.originOr(env.sender());
        if (!r.cell().equals(ctx.self())) {
            Optional<Address> next = route(r.cell(), env.sender());
            if (next.isPresent()) {
                ctx.comm().send(next.get(), r.via(origin));
            } else {
                answer(env, r, origin, InvocationResult.failed(r.call(), TeamContext.truncate("no way to cell '" + r.cell()
                        + "' is known to '" + ctx.self() + "'")));
            }
            return;
        }
        InvocationResult result;
        try {
            Caller caller = new Caller(origin, r.caller());
            Object value = switch (r.kind()) {
                case EVENT -> {
                    ctx.host().receiveEvent(caller, r.path(), r.selector().isEmpty() ? null : r.selector(), r.event(),
                            attributes(r.values().get(0)));
                    yield null;
                }
                case EVALUATE -> ctx.host().evaluate(caller, (String) r.values().get(0), r.selector().equals("test:"));
            };
            result = InvocationResult.ok(r.call(), WireValues.of(value));
            ctx.emit(CellEvent.Kind.DELIVERED, describe(r) + " from " + r.caller() + " on " + origin);
        } catch (ExternalCallException | PonderError | IllegalArgumentException refused) {
            String why = TeamContext.truncate(describe(r) + " from " + r.caller() + " on " + origin + " refused by '"
                    + ctx.self() + "': " + refused.getMessage());
            ctx.emit(CellEvent.Kind.REJECTED, why);
            result = InvocationResult.failed(r.call(), why);
        }
        answer(env, r, origin, result);
    }

    /** Takes the answer to one of this cell's requests; false when it answers none of them. */
    boolean onResult(Envelope env, InvocationResult r) {
        CellRequest request = pending.remove(r.inReplyTo());
        if (request == null) {
            return false;
        }
        ctx.emit(CellEvent.Kind.INVOKED, "call " + r.inReplyTo() + " (" + describe(request) + ") answered by "
                + env.sender() + ": " + (r.ok() ? r.value() : "error " + r.error()));
        answered(request, r);
        return true;
    }

    private void answered(CellRequest request, InvocationResult r) {
        if (!r.ok() && request.kind() == CellRequest.Kind.EVENT) {
            ctx.host().report("EventForwarder: " + describe(request) + ": " + r.error());
        }
        ctx.host().raise("remoteResult", "remoteResult", r.inReplyTo(), r.ok(), r.value(), r.error());
    }

    private static Map<String, Object> attributes(Object wire) {
        if (WireValues.toJava(wire) instanceof Map<?, ?> m) {
            Map<String, Object> out = new LinkedHashMap<>();
            m.forEach((k, v) -> out.put(String.valueOf(k), v));
            return out;
        }
        throw new IllegalArgumentException("a forwarded event carries its attributes as a map; got " + wire);
    }

    private static String describe(CellRequest r) {
        return switch (r.kind()) {
            case EVENT -> "event '" + r.event() + "' forwarded to /team/" + r.cell() + "/" + r.path()
                    + (r.selector().isEmpty() ? "" : " as " + r.selector());
            case EVALUATE -> r.selector() + " on /team/" + r.cell();
        };
    }

    private void answer(Envelope env, CellRequest r, String origin, InvocationResult result) {
        Optional<Address> to = Optional.empty();
        if (!r.reply().isEmpty()) {
            try {
                to = Optional.of(Address.parse(r.reply()));
            } catch (IllegalArgumentException bad) {
                ctx.reject(env, "reply address '" + r.reply() + "' is not host:port; answering the sender");
            }
        }
        if (to.isEmpty()) {
            to = ctx.address(origin).or(() -> ctx.address(env.sender()));
        }
        to.ifPresent(a -> ctx.comm().send(a, result));
    }

    /** Straight to {@code cell} when its address is known, else to the parent (never back to {@code from}). */
    private Optional<Address> route(String cell, String from) {
        Optional<Address> direct = ctx.address(cell);
        if (direct.isPresent()) {
            return direct;
        }
        if (st.parent != null && !st.acting && !st.parent.vehicle().equals(from)) {
            return Optional.of(st.parent.address());
        }
        return Optional.empty();
    }
}
