package net.smc.core.message;

/**
 * Exchanged between a parent and its children to show they are alive: the sender's role, the
 * mission epoch it believes in, a small state code of the role (its meaning belongs to the
 * protocol) and the version of its parent's status the sender holds (0: none from this parent),
 * which lets the parent answer with a bare {@link Echo} while that status is still current. The
 * most frequent message, so its codec path allocates nothing but the records, and its numbers are
 * written as varints (usually one byte each).
 */
public record Heartbeat(String role, long epoch, int state, long statusVersion) implements Message {
    /** A heartbeat that holds no status of its parent's. */
    public Heartbeat(String role, long epoch, int state) {
        this(role, epoch, state, 0);
    }

    public Heartbeat {
        Fields.name("Heartbeat.role", role);
        Fields.nonNegative("Heartbeat.epoch", epoch);
        Fields.nonNegative("Heartbeat.state", state);
        Fields.nonNegative("Heartbeat.statusVersion", statusVersion);
    }

    @Override
    public MessageType type() {
        return MessageType.HEARTBEAT;
    }
}
