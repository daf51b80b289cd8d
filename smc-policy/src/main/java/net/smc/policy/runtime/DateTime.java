package net.smc.policy.runtime;

import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import java.time.Instant;

/** A point in time, loadable as {@code root load: "DateTime"}; {@code create} reads the cell's clock. */
@Managed("DateTime")
public final class DateTime {
    private final long millis;

    @Op("create")
    public DateTime(CallContext ctx) {
        this.millis = ctx.runtime().clock().getAsLong();
    }

    @Op("create:")
    public DateTime(long millis) {
        this.millis = millis;
    }

    /** Milliseconds since the epoch (the name is Ponder2's). */
    @Op("secs")
    public long secs() {
        return millis;
    }

    /** ISO-8601 in UTC, e.g. {@code 2026-01-01T00:00:00Z}. */
    @Op("asString")
    public String asString() {
        return Instant.ofEpochMilli(millis).toString();
    }

    @Override
    public String toString() {
        return asString();
    }
}
