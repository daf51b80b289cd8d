package net.smc.sim.render;

import java.util.Objects;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.LongConsumer;
import java.util.function.LongSupplier;

/**
 * Paces a simulation on virtual time against the wall clock for a live view: each frame it asks
 * the caller to advance the mission by the wall time since the last frame times the
 * {@link ViewControls#speed()} (nothing while paused), then to show a frame, then waits for the
 * next frame's time. The simulation stays on its own virtual clock; only how much of it runs per
 * frame follows the wall clock. A frame that took long does not make the next one catch up by more
 * than {@link #MAX_CATCH_UP_NANOS}: a slow machine shows a slower run, not a jumpy one.
 *
 * <pre>{@code
 * PacedLoop loop = PacedLoop.realTime(window.controls(), 40);
 * loop.run(scheduler::runFor, () -> window.show(world, scene), () -> window.closed() || done());
 * }</pre>
 */
public final class PacedLoop {
    /** The most wall time one frame accounts for, ns. */
    static final long MAX_CATCH_UP_NANOS = TimeUnit.MILLISECONDS.toNanos(250);
    private final ViewControls controls;
    private final long frameNanos;
    private final LongSupplier wallNanos;
    private final Waiter waiter;
    private long last = Long.MIN_VALUE;
    private double carryMillis;

    /** Waits a while; {@code TimeUnit.NANOSECONDS::sleep} for real, a fake clock's advance in tests. */
    @FunctionalInterface
    public interface Waiter {
        void await(long nanos) throws InterruptedException;
    }

    /**
     * @param frameMillis wall-clock time between frames, 5 to 1,000 ms
     * @param wallNanos   the wall clock, ns (any origin)
     * @param waiter      how to wait
     */
    public PacedLoop(ViewControls controls, int frameMillis, LongSupplier wallNanos, Waiter waiter) {
        if (frameMillis < 5 || frameMillis > 1_000) {
            throw new IllegalArgumentException("frame period " + frameMillis + " ms is out of range; it must be 5 to 1000 ms");
        }
        this.controls = Objects.requireNonNull(controls, "controls");
        this.frameNanos = TimeUnit.MILLISECONDS.toNanos(frameMillis);
        this.wallNanos = Objects.requireNonNull(wallNanos, "wallNanos");
        this.waiter = Objects.requireNonNull(waiter, "waiter");
    }

    /** A loop on the real wall clock ({@code System.nanoTime}), sleeping between frames: for a live window only. */
    public static PacedLoop realTime(ViewControls controls, int frameMillis) {
        return new PacedLoop(controls, frameMillis, System::nanoTime, TimeUnit.NANOSECONDS::sleep);
    }

    /**
     * How many milliseconds of mission time to run for the wall time since the previous call
     * (none at the first call and while paused); fractions carry over to the next call.
     */
    public long advanceFor(long nowNanos) {
        long elapsed = last == Long.MIN_VALUE ? 0 : Math.max(0, Math.min(MAX_CATCH_UP_NANOS, nowNanos - last));
        last = nowNanos;
        if (controls.paused()) {
            carryMillis = 0;
            return 0;
        }
        carryMillis += elapsed / 1e6 * controls.speed();
        long whole = (long) Math.floor(carryMillis);
        carryMillis -= whole;
        return whole;
    }

    /**
     * Runs frames until {@code finished} says so: advance the mission ({@code advance} gets
     * milliseconds, e.g. {@code scheduler::runFor}), show a frame, wait for the next frame's time.
     *
     * @return how many frames were shown
     * @throws InterruptedException when the waiting thread is interrupted (the loop stops)
     */
    public long run(LongConsumer advance, Runnable frame, BooleanSupplier finished) throws InterruptedException {
        long frames = 0;
        while (!finished.getAsBoolean()) {
            long start = wallNanos.getAsLong();
            long millis = advanceFor(start);
            if (millis > 0) {
                advance.accept(millis);
            }
            frame.run();
            frames++;
            long wait = start + frameNanos - wallNanos.getAsLong();
            if (wait > 0) {
                waiter.await(wait);
            }
        }
        return frames;
    }
}
