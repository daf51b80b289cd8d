package net.smc.policy.runtime;

import net.smc.policy.api.Nil;
import net.smc.policy.api.PonderError;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import java.math.BigDecimal;

/** The error object an {@code onError:} handler receives. */
@Managed("Error")
public final class ErrorValue {
    private final PonderError error;

    public ErrorValue(PonderError error) {
        this.error = error;
    }

    @Op("message")
    public String message() {
        return error.getMessage();
    }

    @Op("source")
    public Object source() {
        return error.pos() == null ? Nil.NIL : error.pos().source();
    }

    @Op("line")
    public BigDecimal line() {
        return BigDecimal.valueOf(error.pos() == null ? 0 : error.pos().line());
    }

    @Op("char")
    public BigDecimal column() {
        return BigDecimal.valueOf(error.pos() == null ? 0 : error.pos().column());
    }

    @Override
    public String toString() {
        return error.describe();
    }
}
