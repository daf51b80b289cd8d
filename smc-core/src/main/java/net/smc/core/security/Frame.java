package net.smc.core.security;

/** A parsed datagram, before any key is checked: one record per family of {@link FrameCodec} kinds. */
sealed interface Frame permits Frame.Signed, Frame.Hello, Frame.Keyed {

    /** The sender's counter, in full (its low 48 bits travel; see {@link FrameCodec#counterNear}). */
    long counter();

    /** The sender's clock when it sent, in ms: its counter follows the clock shifted left by 20 bits. */
    default long timestampMillis() {
        return counter() >> SecureEndpoint.COUNTER_SHIFT;
    }

    /** A SIGNED datagram: the payload is {@code datagram[payloadStart, signedLength)}, the signature follows. */
    record Signed(Credential credential, long counter, byte[] datagram, int payloadStart, int signedLength) implements Frame {
    }

    /** A HELLO; {@code echo} is all zeros when the sender has seen no key of the recipient's. The signature follows {@code datagram[0, signedLength)}. */
    record Hello(Credential credential, long counter, String recipient, byte[] ephemeral, byte[] echo, byte[] datagram,
                 int signedLength) implements Frame {
    }

    /**
     * A PAIR_MAC, TEAM_MAC or TEAM_KEY datagram. The body is {@code datagram[bodyStart, bodyEnd)}:
     * the payload, with the MAC after it; or, for a TEAM_KEY, the sealed key with its tag.
     */
    record Keyed(int kind, int teamId, String sender, long counter, byte[] datagram, int bodyStart, int bodyEnd) implements Frame {
    }
}
