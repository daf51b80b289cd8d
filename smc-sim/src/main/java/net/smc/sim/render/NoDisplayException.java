package net.smc.sim.render;

/** Thrown when a window is asked for where there is no display (a headless JVM, no X server). */
public final class NoDisplayException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    NoDisplayException(String message) {
        super(message, null, false, false);
    }
}
