package net.smc.sim.robot;

import net.smc.sim.arena.Arena;
import net.smc.sim.hardware.Radio;
import org.dyn4j.dynamics.Body;

/**
 * What a {@link SimRobot} and its sensors need to know of the world they move in: the arena (the
 * things a camera may see, the hazards a chemical sensor smells and that disable a robot), the
 * other robots, ray casts and lines of sight through the physics world, this step's seeded noise,
 * and the radio. The world offers it to each robot it makes; the robot knows nothing else of the
 * world, so the world may step robots without the robots depending on it.
 */
public interface RobotGround {

    /** The arena the robot is in. */
    Arena arena();

    /** Every robot in the world, this one included, in the order they were added. */
    Iterable<SimRobot> robots();

    /**
     * Casts one ray per index from ({@code x[i]}, {@code y[i]}) at {@code angle[i]} (radians), at
     * most {@code maxLength} m, hitting every body but {@code self}; writes each distance to the
     * first hit in {@code out[i]}, or positive infinity when nothing lies within reach.
     */
    void castRays(double[] x, double[] y, double[] angle, double maxLength, Body self, double[] out);

    /** Whether nothing that occludes (walls, closed doors, obstacles) lies between the two points. */
    boolean clearLine(double ax, double ay, double bx, double by);

    /**
     * This step's standard normal draw for a robot's noise {@code stream} and a sensor's
     * {@code channel}: the same for the same stream, step and channel, however often it is asked.
     */
    double gaussian(long stream, int channel);

    /** What {@link #moment()} answers for a ground that does not keep one: sensors then always read anew. */
    long NO_MOMENT = Long.MIN_VALUE;

    /**
     * A number that changes whenever what a sensor reads may have changed: a body moved (the
     * physics stepped), a robot came into the world, or a new step's noise was drawn. While it
     * stays the same a sensor may give its last reading again instead of casting its rays anew.
     * {@link #NO_MOMENT} (the default) promises nothing.
     */
    default long moment() {
        return NO_MOMENT;
    }

    /** The radio of the robot called {@code id}, as its cell uses it. */
    Radio radio(String id);

    /** Told when {@code robot} is disabled, its radio silent from now on: the radio stops its links at once. */
    default void radioOff(SimRobot robot) {
    }
}
