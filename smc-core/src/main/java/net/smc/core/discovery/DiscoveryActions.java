package net.smc.core.discovery;

/**
 * What discovery asks the team protocols to do. The role-assignment protocol implements it; tests
 * use a recording fake.
 */
@FunctionalInterface
public interface DiscoveryActions {

    /**
     * Asks a vehicle for its full capability description, to assign it {@code role} if the
     * description matches (the paper's Algorithm 2). Called on the cell's thread from a policy's
     * action: send the request and return; do not wait for the reply.
     */
    void requestFullCapability(String uav, String role);
}
