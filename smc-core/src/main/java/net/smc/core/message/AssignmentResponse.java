package net.smc.core.message;

/**
 * A vehicle's answer to a {@link RoleAssignment}: whether it took the role, and why not (or an
 * empty reason when it did).
 */
public record AssignmentResponse(long inReplyTo, String role, boolean accepted, String reason) implements Message {
    public AssignmentResponse {
        Fields.name("AssignmentResponse.role", role);
        Fields.text("AssignmentResponse.reason", reason);
    }

    @Override
    public MessageType type() {
        return MessageType.ASSIGNMENT_RESPONSE;
    }
}
