package net.smc.core.role;

/**
 * Carries out a re-assignment that a policy asked for with
 * {@code root/role/<manager> reassign: role scheme: "default"} (the paper's Table II). The team
 * protocols implement it (find a free vehicle, hand over the role and the state worth keeping, or
 * contract the team); the Role-Manager only checks that the asking role manages the role.
 */
@FunctionalInterface
public interface Reassignment {

    /**
     * Called on the cell's thread, inside the policy's action: do not block.
     *
     * @param managingRole the role whose policy asked (it manages {@code role})
     * @param role         the role to re-assign
     * @param scheme       the re-assignment scheme the policy named ({@code "default"})
     */
    void reassign(String managingRole, String role, String scheme);

    /** Refuses every request: for cells whose team protocols do not re-assign. */
    Reassignment NONE = (managingRole, role, scheme) -> {
        throw new UnsupportedOperationException("this cell has no re-assignment service; role '" + managingRole
                + "' cannot re-assign '" + role + "'");
    };
}
