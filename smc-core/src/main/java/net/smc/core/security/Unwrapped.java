package net.smc.core.security;

import java.util.Objects;
import java.util.Optional;

/** What {@link SecureEndpoint#unwrap} made of a datagram: a payload to deliver, a handshake step, or a refusal. */
public sealed interface Unwrapped permits Unwrapped.Delivered, Unwrapped.Control, Unwrapped.Rejected {

    /**
     * An authenticated payload, for the layer above.
     *
     * @param sender     the sender's vehicle id, as authenticated by {@code protection}
     * @param protection how it was protected
     * @param payload    the payload (a fresh array, the caller's to keep)
     */
    record Delivered(String sender, Protection protection, byte[] payload) implements Unwrapped {
        public Delivered {
            Objects.requireNonNull(sender, "sender");
            Objects.requireNonNull(protection, "protection");
            Objects.requireNonNull(payload, "payload");
        }
    }

    /**
     * A message of this layer's own (handshake, team key), handled; nothing for the layer above.
     *
     * @param sender the authenticated sender
     * @param event  what happened
     * @param reply  a datagram to send back to the sender, or null
     */
    record Control(String sender, ControlEvent event, byte[] reply) implements Unwrapped {
        public Control {
            Objects.requireNonNull(sender, "sender");
            Objects.requireNonNull(event, "event");
        }

        /** The datagram to send back to the sender, if any. */
        public Optional<byte[]> replyDatagram() {
            return Optional.ofNullable(reply);
        }
    }

    /**
     * A refused datagram; it has been counted and changed nothing.
     *
     * @param reason        why
     * @param claimedSender the sender id the datagram claims (unproven), or null when none could be read
     * @param detail        what was wrong, naming the message kind and claimed sender where they could be read
     */
    record Rejected(Rejection reason, String claimedSender, String detail) implements Unwrapped {
        public Rejected {
            Objects.requireNonNull(reason, "reason");
            Objects.requireNonNull(detail, "detail");
        }
    }

    /** The handshake and key events a {@link Control} reports. */
    enum ControlEvent {
        /**
         * The peer's handshake echoed this endpoint's current key and brought one the session was not
         * derived from: session keys were derived (a new session, or a new one replacing the old after
         * the peer restarted). A reply comes with it, so that the peer can agree too.
         */
        KEYS_AGREED,
        /**
         * The peer's handshake echoed this endpoint's key and brought the one the session stands on (a
         * retry, or the last step); the session stands. No reply.
         */
        HANDSHAKE_REPEATED,
        /**
         * The peer's handshake does not echo this endpoint's current key: the peer's first step, or a
         * recorded HELLO replayed (perhaps to a vehicle that restarted since). Nothing is agreed; the
         * reply offers this endpoint's key, and keys are derived only from a HELLO that echoes it.
         */
        HANDSHAKE_OFFERED,
        /** A team key arrived from a session peer and is now the one in use. */
        TEAM_KEY_INSTALLED
    }
}
