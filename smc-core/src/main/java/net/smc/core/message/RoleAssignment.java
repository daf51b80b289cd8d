package net.smc.core.message;

import java.util.List;

/**
 * Gives a vehicle a role: the mission, the role, the vehicle's identity in the team, its parent
 * (the vehicle id of its manager), the policies of the role (and of the roles it manages, which a
 * manager serves on to its own children), by URI and version, the team configuration's epoch, the
 * state handed over from the role's previous holder (empty for a new role), and the other seats
 * ({@code role#slot}) the vehicle keeps from the same parent: whatever else it holds from that parent
 * it gives up, so parent and child agree on what the child holds, and the assigner's ancestors
 * (its parent's vehicle id first, up to the commander), so that a vehicle never takes a role from its
 * own descendant. The identity belongs to the assignment's mission. Answered by an {@link AssignmentResponse}.
 */
public record RoleAssignment(String mission, String role, Identity identity, String parent, List<PolicyRef> policies,
                             long epoch, List<Object> handover, List<String> keeps, List<String> ancestors)
        implements Message {
    /** The most ancestors a message names: deeper trees are cut off at the top. */
    public static final int MAX_ANCESTORS = 16;
    /** The most seats an assignment lets a vehicle keep. */
    public static final int MAX_KEEPS = 32;

    /** An assignment in epoch 0 with nothing handed over and nothing else kept. */
    public RoleAssignment(String mission, String role, Identity identity, String parent, List<PolicyRef> policies) {
        this(mission, role, identity, parent, policies, 0, List.of(), List.of(), List.of());
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
        handover = ValueLimits.list("RoleAssignment.handover", handover);
        keeps = Fields.list("RoleAssignment.keeps", keeps, MAX_KEEPS);
        ancestors = Fields.list("RoleAssignment.ancestors", ancestors, MAX_ANCESTORS);
        for (String a : ancestors) {
            Fields.string("RoleAssignment.ancestors[]", a, 1, WireFormat.MAX_SENDER, "a vehicle id");
        }
        for (String k : keeps) {
            Fields.string("RoleAssignment.keeps[]", k, 1, WireFormat.MAX_NAME + 11, "a seat role#slot");
        }
    }

    @Override
    public MessageType type() {
        return MessageType.ROLE_ASSIGNMENT;
    }
}
