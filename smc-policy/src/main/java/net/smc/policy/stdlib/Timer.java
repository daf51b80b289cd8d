package net.smc.policy.stdlib;

import java.util.LinkedHashMap;
import java.util.Map;
import net.smc.policy.lang.SourcePos;
import net.smc.policy.runtime.CallContext;
import net.smc.policy.runtime.CellRuntime;
import net.smc.policy.runtime.EventTemplate;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.api.PonderError;

/**
 * Ponder2's multiple timer: each {@code tick:event:} (once) or {@code repeat:event:} (periodic)
 * makes a ticker, numbered from 1, that raises the event after the time given, on the cell's
 * scheduler (so in a simulation, in virtual time). A time is milliseconds ({@code 1500}) or
 * {@code [hh:]mm:ss} ({@code "0:22"} is 22 seconds). An event with a {@code count} attribute gets
 * the tick number (1, 2, ...; it goes on counting across {@code stop:}/{@code start:}). The event
 * is raised with the sender of {@code tick:event:} as its source. If the event cannot be raised
 * (its template wants attributes other than {@code count}), the error is reported and that ticker
 * stops; errors inside the policies it triggers are theirs and do not stop it.
 */
@Managed("Timer")
final class Timer {
    private final CellRuntime runtime;
    private final Map<Integer, Ticker> tickers = new LinkedHashMap<>();
    private int lastIndex;

    @Op("create")
    Timer(CallContext ctx) {
        this.runtime = ctx.runtime();
    }

    @Op("tick:event:")
    int tick(CallContext ctx, String time, EventTemplate event) {
        return add(new Ticker(ctx, false, decode(time, false), event));
    }

    @Op("repeat:event:")
    int repeat(CallContext ctx, String time, EventTemplate event) {
        return add(new Ticker(ctx, true, decode(time, true), event));
    }

    private int add(Ticker ticker) {
        tickers.put(++lastIndex, ticker);
        ticker.start();
        return lastIndex;
    }

    /** Starts a stopped ticker again with a full interval; a running one goes on as it was. */
    @Op("start:")
    void start(int index) {
        Ticker t = tickers.get(index);
        if (t != null) {
            t.start();
        }
    }

    @Op("stop:")
    void stop(int index) {
        Ticker t = tickers.get(index);
        if (t != null) {
            t.stop();
        }
    }

    /** Stops every ticker; their numbers mean nothing afterwards. */
    @Op("cancel")
    void cancel() {
        tickers.values().forEach(Ticker::stop);
        tickers.clear();
    }

    @Op("cancel:")
    void cancel(int index) {
        Ticker t = tickers.remove(index);
        if (t != null) {
            t.stop();
        }
    }

    /** Extension: whether ticker {@code index} is waiting to fire. */
    @Op("isRunning:")
    boolean isRunning(int index) {
        Ticker t = tickers.get(index);
        return t != null && t.cancelHandle != null;
    }

    /** Milliseconds of a time string: digits, or {@code [hh:]mm:ss}. */
    static long decode(String time, boolean repeat) {
        long millis;
        try {
            String[] parts = time.split(":", -1);
            if (parts.length > 3) {
                throw new NumberFormatException();   // [hh:]mm:ss has three fields at most
            }
            if (parts.length == 1) {
                millis = Long.parseLong(time);
            } else {
                long seconds = 0;
                for (String part : parts) {
                    long n = Long.parseLong(part);
                    if (n < 0) {
                        throw new NumberFormatException();
                    }
                    seconds = Math.addExact(Math.multiplyExact(seconds, 60), n);
                }
                millis = Math.multiplyExact(seconds, 1000);
            }
        } catch (NumberFormatException | ArithmeticException e) {
            throw new PonderError("Bad time string: " + time);
        }
        if (millis < 0) {
            throw new PonderError("Bad time string: " + time);
        }
        if (repeat && millis == 0) {
            throw new PonderError("a repeating timer needs a period of at least 1 ms, got " + time);
        }
        return millis;
    }

    private final class Ticker {
        private final Object source;
        private final boolean repeat;
        private final long millis;
        private final EventTemplate event;
        private final SourcePos madeAt;
        private long count = 1;
        private Runnable cancelHandle;

        Ticker(CallContext ctx, boolean repeat, long millis, EventTemplate event) {
            this.source = ctx.subject();
            this.repeat = repeat;
            this.millis = millis;
            this.event = event;
            this.madeAt = ctx.pos();
        }

        void start() {
            if (cancelHandle == null) {
                cancelHandle = runtime.schedule(millis, this::fire);
            }
        }

        void stop() {
            if (cancelHandle != null) {
                cancelHandle.run();
                cancelHandle = null;
            }
        }

        private void fire() {
            cancelHandle = repeat ? runtime.schedule(millis, this::fire) : null;
            Object[] values = new Object[event.attributeNames().size()];
            for (int i = 0; i < values.length; i++) {
                String name = event.attributeNames().get(i);
                if (!name.equals("count")) {
                    stop();
                    throw new PonderError("Timer: cannot raise the event: hash key '" + name + "' not found; the timer stopped",
                            madeAt);
                }
                values[i] = java.math.BigDecimal.valueOf(count);
            }
            count++;
            event.raise(runtime.newExecution(source), values);
        }
    }
}
