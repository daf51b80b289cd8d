package net.smc.core.cell;

import net.smc.core.mission.TeamParameters;

/**
 * How a team organises its management (the comparison of the paper's section V).
 */
public enum Scheme {
    /**
     * The paper's scheme: each role discovers and assigns the roles it manages, so the management
     * tree follows the mission class (the commander finds surveyors, surveyors find their detectors
     * and relays).
     */
    DISTRIBUTED,
    /** The commander discovers and assigns every role itself: a flat tree of depth one. */
    CENTRALISED;

    /**
     * The scheme a mission parameter names: {@code distributed} or {@code centralised} (also
     * {@code centralized}), in any case.
     *
     * @throws IllegalArgumentException naming the value and the accepted ones
     */
    public static Scheme parse(String text) {
        return TeamParameters.scheme(text).equals("distributed") ? DISTRIBUTED : CENTRALISED;
    }
}
