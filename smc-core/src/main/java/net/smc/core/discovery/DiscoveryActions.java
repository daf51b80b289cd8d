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

    /**
     * Holds ({@code true}) or resumes ({@code false}) the cell's recruiting: while held, as a
     * manager it sends no discovery broadcast and so assigns no role; the role-missions decide when
     * a team is assembled (the rescue's commander, when a soldier calls for help).
     *
     * @throws UnsupportedOperationException when the cell has no team protocols to hold
     */
    default void holdRecruiting(boolean held) {
        throw new UnsupportedOperationException("this cell does not recruit, so its recruiting cannot be "
                + (held ? "held" : "resumed"));
    }

    /** Whether {@link #holdRecruiting} holds the cell's recruiting now. */
    default boolean recruitingHeld() {
        return false;
    }
}
