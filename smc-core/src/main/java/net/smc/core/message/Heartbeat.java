package net.smc.core.message;

/**
 * Exchanged between a parent and its children to show they are alive: the sender's role, the
 * mission epoch it believes in and a small state code of the role (its meaning belongs to the
 * protocol). The most frequent message, so its codec path allocates nothing but the records.
 */
public record Heartbeat(String role, long epoch, int state) implements Message {
    public Heartbeat {
        Fields.name("Heartbeat.role", role);
        Fields.nonNegative("Heartbeat.epoch", epoch);
        Fields.nonNegative("Heartbeat.state", state);
    }

    @Override
    public MessageType type() {
        return MessageType.HEARTBEAT;
    }
}
