package net.smc.core.comm;

import java.util.Collection;
import java.util.EnumSet;
import java.util.Objects;
import java.util.Set;

import net.smc.core.message.MessageType;

/**
 * The message types that travel reliably: the {@link CommunicationManager} sends them through the
 * {@link MessageSender} (acknowledged, retransmitted, reported failed) and, on receipt, acknowledges
 * them and delivers each only once. Every other type is connectionless, as UDP is.
 *
 * <p>Both ends decide by type, because the wire format has no "reliable" flag: <b>every cell of a
 * team must use the same set</b>, or a sender waits for Acks a receiver never sends.
 *
 * <p>{@link #DEFAULT} holds the exchanges the paper names as critical (section IV-A: role
 * assignment, capability descriptions) and the other request/reply pairs whose loss would stall a
 * protocol: ROLE_ASSIGNMENT, ASSIGNMENT_RESPONSE, CAPABILITY_REQUEST, CAPABILITY_REPLY,
 * POLICY_REQUEST, POLICY_REPLY, INVOCATION, INVOCATION_RESULT, CELL_REQUEST, and ROLE_EVENT (an event a role
 * publishes for other vehicles' roles happens once: a lost hazard report is a lost hazard).
 * Discovery, heartbeats and subtree reports stay connectionless: they repeat by design, and a
 * heartbeat's loss is the very thing a failure detector measures.
 *
 * @param types the critical types; never ACK (an Ack is the receipt itself and is not acknowledged)
 */
public record CriticalTypes(Set<MessageType> types) {

    /** The default set; see the class comment. */
    public static final CriticalTypes DEFAULT = of(MessageType.ROLE_ASSIGNMENT, MessageType.ASSIGNMENT_RESPONSE,
            MessageType.CAPABILITY_REQUEST, MessageType.CAPABILITY_REPLY, MessageType.POLICY_REQUEST,
            MessageType.POLICY_REPLY, MessageType.INVOCATION, MessageType.INVOCATION_RESULT, MessageType.ROLE_EVENT,
            MessageType.CELL_REQUEST);

    public CriticalTypes {
        Objects.requireNonNull(types, "types");
        EnumSet<MessageType> copy = EnumSet.noneOf(MessageType.class);
        for (MessageType t : types) {
            if (t == null) {
                throw new IllegalArgumentException("critical types contain null; every entry must be a message type");
            }
            copy.add(t);
        }
        if (copy.contains(MessageType.ACK)) {
            throw new IllegalArgumentException("ACK cannot be a critical type: an Ack confirms a message and is"
                    + " never acknowledged itself, or every Ack would be answered by another");
        }
        types = Set.copyOf(copy);
    }

    public static CriticalTypes of(MessageType... types) {
        return new CriticalTypes(Set.of(types));
    }

    public static CriticalTypes of(Collection<MessageType> types) {
        return new CriticalTypes(Set.copyOf(types));
    }

    /** No critical types: everything connectionless. */
    public static CriticalTypes none() {
        return new CriticalTypes(Set.of());
    }

    /** Whether messages of {@code type} are sent reliably. */
    public boolean contains(MessageType type) {
        return types.contains(type);
    }

    /** This set with {@code type} added. */
    public CriticalTypes with(MessageType type) {
        EnumSet<MessageType> more = types.isEmpty() ? EnumSet.noneOf(MessageType.class) : EnumSet.copyOf(types);
        more.add(type);
        return new CriticalTypes(more);
    }

    /** This set without {@code type}. */
    public CriticalTypes without(MessageType type) {
        EnumSet<MessageType> fewer = types.isEmpty() ? EnumSet.noneOf(MessageType.class) : EnumSet.copyOf(types);
        fewer.remove(type);
        return new CriticalTypes(fewer);
    }
}
