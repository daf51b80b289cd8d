package net.smc.sim.render;

import java.util.Locale;

/**
 * The state a viewer changes with keys, read by the loop that advances the simulation: paused or
 * not, the speed (mission seconds per wall-clock second, on a ladder from 1/8 to 64) and the
 * overlays. Keys: space pauses and resumes, {@code +} (or {@code =}) speeds up, {@code -} slows
 * down, {@code r} toggles the infrared rays, {@code c} the camera cones, {@code l} the radio links,
 * {@code t} the trajectories. Thread-safe: the window's event thread writes, the simulation's reads.
 */
public final class ViewControls {
    /** The speeds {@code +} and {@code -} step through. */
    static final double[] SPEEDS = {0.125, 0.25, 0.5, 1, 2, 4, 8, 16, 32, 64};
    private boolean paused;
    private int speed;
    private Overlays overlays;

    /** Running, at the ladder's speed nearest {@code speed}, with {@code overlays}. */
    public ViewControls(double speed, Overlays overlays) {
        if (!(speed > 0) || Double.isInfinite(speed)) {
            throw new IllegalArgumentException("view speed " + speed + " is not a positive finite number; it must be");
        }
        int nearest = 0;
        for (int i = 0; i < SPEEDS.length; i++) {
            if (Math.abs(Math.log(SPEEDS[i] / speed)) < Math.abs(Math.log(SPEEDS[nearest] / speed))) {
                nearest = i;
            }
        }
        this.speed = nearest;
        this.overlays = java.util.Objects.requireNonNull(overlays, "overlays");
    }

    /** Real time, trajectories and legend. */
    public static ViewControls defaults() {
        return new ViewControls(1, Overlays.defaults());
    }

    /**
     * Acts on a typed key.
     *
     * @return whether the key means something here
     */
    public synchronized boolean key(char key) {
        switch (Character.toLowerCase(key)) {
            case ' ' -> paused = !paused;
            case '+', '=' -> speed = Math.min(SPEEDS.length - 1, speed + 1);
            case '-', '_' -> speed = Math.max(0, speed - 1);
            case 'r' -> overlays = overlays.withIrRays(!overlays.irRays());
            case 'c' -> overlays = overlays.withCameraCones(!overlays.cameraCones());
            case 'l' -> overlays = overlays.withRadioLinks(!overlays.radioLinks());
            case 't' -> overlays = overlays.withTrajectories(!overlays.trajectories());
            default -> {
                return false;
            }
        }
        return true;
    }

    public synchronized boolean paused() {
        return paused;
    }

    public synchronized void paused(boolean paused) {
        this.paused = paused;
    }

    /** Mission seconds per wall-clock second. */
    public synchronized double speed() {
        return SPEEDS[speed];
    }

    public synchronized Overlays overlays() {
        return overlays;
    }

    /** A status line for the window's title: speed and pause. */
    public synchronized String status() {
        String x = SPEEDS[speed] >= 1 ? String.format(Locale.ROOT, "%.0fx", SPEEDS[speed])
                : String.format(Locale.ROOT, "1/%.0fx", 1 / SPEEDS[speed]);
        return x + (paused ? ", paused" : "") + "  (space pause, +/- speed, r IR, c camera, l radio, t paths)";
    }
}
