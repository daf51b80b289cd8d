package net.smc.core.message;

/**
 * A parent's answer to a heartbeat when the child already holds the parent's current
 * {@link Status} (the heartbeat named its version): the {@linkplain #tagOf tag} of the heartbeat it
 * answers (0 when it renews no lease), which renews the child's lease as a status's echo does. In
 * the steady state this is the only answer, so the parent's half of the heartbeat exchange costs
 * four bytes of payload instead of the whole status.
 *
 * <p>The tag is the heartbeat's envelope id modulo 2<sup>32</sup> − 1, plus one: 1 to
 * 2<sup>32</sup> − 1, never 0. The child matches it against the heartbeats it sent recently (the
 * last 64, half a minute at the usual period): ids within that window differ by far less than
 * 2<sup>32</sup> − 1 (a cell would have to send thousands of millions of messages in it), so the tag
 * names one of them.
 */
public record Echo(long echo) implements Message {
    /** The largest tag. */
    public static final long MAX_TAG = 0xFFFF_FFFFL;

    public Echo {
        if (echo < 0 || echo > MAX_TAG) {
            throw new IllegalArgumentException("Echo.echo is " + echo + "; it must be 0 (none) to " + MAX_TAG
                    + " (a heartbeat's tag)");
        }
    }

    /** The tag of the heartbeat with envelope id {@code id} (ids are at least 1). */
    public static long tagOf(long id) {
        return Long.remainderUnsigned(id, MAX_TAG) + 1;
    }

    @Override
    public MessageType type() {
        return MessageType.ECHO;
    }
}
