package net.smc.core.message;

import java.util.List;

/**
 * Gives a vehicle a role: the mission, the role, the vehicle's identity in the team, its parent
 * (the vehicle id of its manager), the policies of the role (and of the roles it manages, which a
 * manager serves on to its own children), by URI and version, the team configuration's epoch, and
 * the state handed over from the role's previous holder (empty for a new role). The identity
 * belongs to the assignment's mission. Answered by an {@link AssignmentResponse}.
 */
public record RoleAssignment(String mission, String role, Identity identity, String parent, List<PolicyRef> policies,
                             long epoch, List<Object> handover) implements Message {
    /** An assignment in epoch 0 with nothing handed over. */
    public RoleAssignment(String mission, String role, Identity identity, String parent, List<PolicyRef> policies) {
        this(mission, role, identity, parent, policies, 0, List.of());
    }

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
        Fields.nonNegative("RoleAssignment.epoch", epoch);
        handover = Values.list("RoleAssignment.handover", handover);
    }

    @Override
    public MessageType type() {
        return MessageType.ROLE_ASSIGNMENT;
    }
}
