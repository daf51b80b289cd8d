package net.smc.sim.hardware;

import java.util.List;

/** A chemical sensor: detects hazards whose substance reaches the robot. */
public interface ChemicalSensor {

    /**
     * One hazard sensed.
     *
     * @param tag      the hazard's tag
     * @param kind     its kind ({@code chemical}, {@code radiation} ...)
     * @param strength 0..1, rising as the robot nears the hazard's centre
     */
    record Reading(String tag, String kind, double strength) {
    }

    /** The radius within which a hazard is sensed, m. */
    double radius();

    /** The hazards sensed now, strongest first. */
    List<Reading> sense();
}
