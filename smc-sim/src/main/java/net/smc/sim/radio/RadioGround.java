package net.smc.sim.radio;

/**
 * What the radio needs to know of the world it works in: where its nodes (robots and fixed
 * stations) are, whether their radios are on, and how many walls stand between two points. The
 * world offers it to its {@link WorldRadio}; the radio knows nothing else of the world.
 */
public interface RadioGround {

    /** The world's step count: positions change only from one step to the next. */
    long steps();

    /** The world's step period, ms of mission time. */
    int stepMillis();

    /** How many nodes there are now; it grows when robots are added. */
    int nodeCount();

    /** The id of every robot and station, in no particular order. */
    Iterable<String> nodeIds();

    /** The robot or station called {@code id} (a robot before a station of that id), or null. */
    Node node(String id);

    /** How many radio-blocking walls the segment from a to b crosses, counting no further than {@code limit + 1}. */
    int wallsBetween(double ax, double ay, double bx, double by, int limit);

    /** One robot or station as the radio sees it; a live view of where it is now. */
    interface Node {
        double x();

        double y();

        /** Whether its radio works: a disabled robot's is silent both ways; a station's always works. */
        boolean radioOn();
    }
}
