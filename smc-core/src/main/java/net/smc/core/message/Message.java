package net.smc.core.message;

/**
 * The body of a datagram exchanged between cells: one closed family of immutable records, one per
 * {@link MessageType}. Every record checks its fields in its constructor against the limits of
 * {@link WireFormat}, so a message that exists can always be encoded, and a decoded datagram is
 * turned into a message through the same checks.
 *
 * <p>Records that answer a request carry {@code inReplyTo}, the {@link Envelope#id() id} of the
 * request from the same peer.
 */
public sealed interface Message permits Discovery, DiscoveryReply, CapabilityRequest, CapabilityReply,
        RoleAssignment, AssignmentResponse, PolicyRequest, PolicyReply, Heartbeat, Ack, RoleEvent,
        Invocation, InvocationResult, Leave, Status, Acks, Roster, SubtreeReport,
        CellRequest, Echo, Withdrawal {

    /** The type of this message, which names it on the wire and in the Message-Router. */
    MessageType type();
}
