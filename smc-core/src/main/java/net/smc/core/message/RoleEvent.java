package net.smc.core.message;

import java.util.List;

/**
 * An event a role publishes for the roles of other vehicles that require it (the paper's section
 * II-B.2.A, items iii and v): the publishing role, the event name, its values as PonderTalk values
 * (String, BigDecimal, Boolean, null or lists of those) and the vehicle that published it. Cells
 * pass it along the management tree towards the roles that require the event; each receiving
 * cell raises it there with the publisher as the subject, {@code root/role/<role>/peers/<role>/<origin>}.
 * A refusal (not required there, or denied) is answered with a failed {@link InvocationResult}
 * whose {@code inReplyTo} is this message's envelope id.
 *
 * @param origin the publishing vehicle; empty means the sender of the envelope
 */
public record RoleEvent(String role, String event, List<Object> values, String origin) implements Message {
    public RoleEvent {
        Fields.name("RoleEvent.role", role);
        Fields.name("RoleEvent.event", event);
        values = ValueLimits.list("RoleEvent.values", values);
        Fields.string("RoleEvent.origin", origin, 0, WireFormat.MAX_SENDER, "a vehicle id, or empty for the sender");
    }

    /** An event published by the sender itself. */
    public RoleEvent(String role, String event, List<Object> values) {
        this(role, event, values, "");
    }

    /** The publishing vehicle: {@link #origin()}, or {@code sender} when that is empty. */
    public String originOr(String sender) {
        return origin.isEmpty() ? sender : origin;
    }

    @Override
    public MessageType type() {
        return MessageType.ROLE_EVENT;
    }
}
