package net.smc.sim.arena;

/**
 * What a body in the world is: the user data of every dyn4j body the world makes, read by the
 * sensors that hit it.
 *
 * @param kind what sort of thing it is
 * @param tag  its tag, as the camera reports it ({@code soldier}, {@code hazard:h1}, a robot's id)
 */
public record Thing(Kind kind, String tag) {

    /** The sorts of things in a world. */
    public enum Kind {
        WALL, DOOR, OBSTACLE, HAZARD, TARGET, ROBOT;

        /** Whether it hides what lies behind it from the camera. */
        public boolean occludes() {
            return this == WALL || this == DOOR || this == OBSTACLE;
        }

        /** Whether it attenuates radio signals crossing it. */
        public boolean blocksRadio() {
            return this == WALL || this == DOOR;
        }
    }
}
