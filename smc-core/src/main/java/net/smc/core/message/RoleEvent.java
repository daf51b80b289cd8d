package net.smc.core.message;

import java.util.List;

/**
 * An event raised by a role that another vehicle's role listens to (the external interface of a
 * role): the raising role, the event name and its values as PonderTalk values (String, BigDecimal,
 * Boolean, null or lists of those).
 */
public record RoleEvent(String role, String event, List<Object> values) implements Message {
    public RoleEvent {
        Fields.name("RoleEvent.role", role);
        Fields.name("RoleEvent.event", event);
        values = ValueLimits.list("RoleEvent.values", values);
    }

    @Override
    public MessageType type() {
        return MessageType.ROLE_EVENT;
    }
}
