package net.smc.core.role;

import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;

/**
 * The subject that stands for a collaborating role's cell inside a receiving role:
 * {@code root/role/<receiver>/peers/<role>/<cell>}. External invocations are sent with it as their
 * subject, so the receiving role's authorisation policies decide them.
 */
@Managed("Peer")
final class Peer {
    private final Caller caller;

    Peer(Caller caller) {
        this.caller = caller;
    }

    @Op("cell")
    public String cell() {
        return caller.cell();
    }

    @Op("role")
    public String role() {
        return caller.role();
    }
}
