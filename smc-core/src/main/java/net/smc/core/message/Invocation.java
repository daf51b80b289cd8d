package net.smc.core.message;

import java.util.List;

/**
 * Calls an operation of a role on another vehicle (the paper's section II-B.2.A, items ii and iv):
 * the target role, the operation and its arguments as PonderTalk values, and who calls. Cells pass
 * it along the management tree to a holder of the role, which answers with an
 * {@link InvocationResult} whose {@code inReplyTo} is {@link #call()}.
 *
 * <p>A management request of a parent to its child ({@code release}) has call 0, no caller role
 * and no answer.
 *
 * @param caller the role the caller acts in; empty for a parent's management request
 * @param call   the caller's number for this call (its answer's {@code inReplyTo}); 0: no answer wanted
 * @param origin the calling vehicle; empty means the sender of the envelope
 * @param reply  where the answer goes ({@code host:port}); empty means back to the sender
 */
public record Invocation(String role, String operation, List<Object> args, String caller, long call, String origin,
                         String reply) implements Message {
    public Invocation {
        Fields.name("Invocation.role", role);
        Fields.name("Invocation.operation", operation);
        args = ValueLimits.list("Invocation.args", args);
        Fields.string("Invocation.caller", caller, 0, WireFormat.MAX_NAME, "a role name, or empty");
        Fields.nonNegative("Invocation.call", call);
        Fields.string("Invocation.origin", origin, 0, WireFormat.MAX_SENDER, "a vehicle id, or empty for the sender");
        Fields.text("Invocation.reply", reply);
    }

    /** A parent's management request: no caller role, no answer. */
    public Invocation(String role, String operation, List<Object> args) {
        this(role, operation, args, "", 0, "", "");
    }

    /** The calling vehicle: {@link #origin()}, or {@code sender} when that is empty. */
    public String originOr(String sender) {
        return origin.isEmpty() ? sender : origin;
    }

    @Override
    public MessageType type() {
        return MessageType.INVOCATION;
    }
}
