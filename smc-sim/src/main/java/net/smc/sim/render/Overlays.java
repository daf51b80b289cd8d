package net.smc.sim.render;

/**
 * Which optional layers a picture shows on top of the arena and the robots.
 *
 * @param irRays       each robot's infrared rays, to what they hit
 * @param cameraCones  each robot's camera field of view and range
 * @param radioLinks   the radio links between robots and stations, opaque as their quality
 * @param trajectories each robot's path so far (when the scene has a {@link TrajectoryRecorder})
 * @param legend       the legend and the scale bar
 */
public record Overlays(boolean irRays, boolean cameraCones, boolean radioLinks, boolean trajectories, boolean legend) {

    /** Trajectories and legend; no sensors, no radio. */
    public static Overlays defaults() {
        return new Overlays(false, false, false, true, true);
    }

    /** Everything on. */
    public static Overlays all() {
        return new Overlays(true, true, true, true, true);
    }

    public Overlays withIrRays(boolean on) {
        return new Overlays(on, cameraCones, radioLinks, trajectories, legend);
    }

    public Overlays withCameraCones(boolean on) {
        return new Overlays(irRays, on, radioLinks, trajectories, legend);
    }

    public Overlays withRadioLinks(boolean on) {
        return new Overlays(irRays, cameraCones, on, trajectories, legend);
    }

    public Overlays withTrajectories(boolean on) {
        return new Overlays(irRays, cameraCones, radioLinks, on, legend);
    }

    public Overlays withLegend(boolean on) {
        return new Overlays(irRays, cameraCones, radioLinks, trajectories, on);
    }
}
