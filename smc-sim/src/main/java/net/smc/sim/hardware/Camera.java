package net.smc.sim.hardware;

import java.util.List;

/** A forward camera that reports tagged objects within its field of view, range and line of sight. */
public interface Camera {

    /** The full field of view, radians. */
    double fieldOfView();

    /** The range, m. */
    double range();

    /** What the camera sees now, nearest first. */
    List<Sighting> look();
}
