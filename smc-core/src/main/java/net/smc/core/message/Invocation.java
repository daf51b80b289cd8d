package net.smc.core.message;

import java.util.List;

/**
 * Calls an operation of a role on another vehicle: the target role, the operation and its
 * arguments as PonderTalk values. Answered by an {@link InvocationResult}.
 */
public record Invocation(String role, String operation, List<Object> args) implements Message {
    public Invocation {
        Fields.name("Invocation.role", role);
        Fields.name("Invocation.operation", operation);
        args = ValueLimits.list("Invocation.args", args);
    }

    @Override
    public MessageType type() {
        return MessageType.INVOCATION;
    }
}
