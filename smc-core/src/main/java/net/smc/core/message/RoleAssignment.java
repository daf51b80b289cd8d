package net.smc.core.message;

import java.util.List;

/**
 * Gives a vehicle a role: the mission, the role, the vehicle's identity in the team, its parent
 * (the vehicle id of its manager) and the policies of the role, by URI and version. The identity
 * belongs to the assignment's mission. Answered by an {@link AssignmentResponse}.
 */
public record RoleAssignment(String mission, String role, Identity identity, String parent, List<PolicyRef> policies)
        implements Message {
    public RoleAssignment {
        Fields.name("RoleAssignment.mission", mission);
        Fields.name("RoleAssignment.role", role);
        Fields.present("RoleAssignment.identity", identity);
        if (!identity.mission().equals(mission)) {
            throw new IllegalArgumentException("RoleAssignment.identity " + identity + " is for mission "
                    + Fields.show(identity.mission()) + "; it must be for the assignment's mission "
                    + Fields.show(mission));
        }
        Fields.string("RoleAssignment.parent", parent, 1, WireFormat.MAX_SENDER, "a vehicle id");
        policies = Fields.list("RoleAssignment.policies", policies, WireFormat.MAX_POLICIES);
    }

    @Override
    public MessageType type() {
        return MessageType.ROLE_ASSIGNMENT;
    }
}
