package net.smc.core.message;

/**
 * A parent's answer to a heartbeat when the child already holds the parent's current
 * {@link Status} (the heartbeat named its version): only the envelope id of the heartbeat it
 * answers (0 when it renews no lease), which renews the child's lease as a status's echo does. In
 * the steady state this is the only answer, so the parent's half of the heartbeat exchange costs
 * a few bytes of payload instead of the whole status.
 */
public record Echo(long echo) implements Message {
    public Echo {
        Fields.nonNegative("Echo.echo", echo);
    }

    @Override
    public MessageType type() {
        return MessageType.ECHO;
    }
}
