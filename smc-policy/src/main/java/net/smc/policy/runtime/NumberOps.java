package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;
import net.smc.policy.api.Op;
import java.math.BigDecimal;

/** Operations of numbers ({@link BigDecimal}, as Ponder2). */
final class NumberOps {
    private NumberOps() {
    }

    @Op("+")
    static BigDecimal plus(BigDecimal self, BigDecimal other) {
        return Numbers.add(self, other);
    }

    @Op("-")
    static BigDecimal minus(BigDecimal self, BigDecimal other) {
        return Numbers.subtract(self, other);
    }

    @Op("*")
    static BigDecimal times(BigDecimal self, BigDecimal other) {
        return Numbers.multiply(self, other);
    }

    @Op("/")
    static BigDecimal divide(BigDecimal self, BigDecimal other) {
        return Numbers.divide(self, other);
    }

    @Op("<")
    static boolean less(BigDecimal self, BigDecimal other) {
        return self.compareTo(other) < 0;
    }

    @Op(">")
    static boolean greater(BigDecimal self, BigDecimal other) {
        return self.compareTo(other) > 0;
    }

    @Op("<=")
    static boolean lessOrEqual(BigDecimal self, BigDecimal other) {
        return self.compareTo(other) <= 0;
    }

    @Op(">=")
    static boolean greaterOrEqual(BigDecimal self, BigDecimal other) {
        return self.compareTo(other) >= 0;
    }

    /** Runs the block for 0 up to the receiver minus one. */
    @Op("do:")
    static BigDecimal each(CallContext ctx, BigDecimal self, Block body) {
        long n = count(self);
        for (long i = 0; i < n; i++) {
            ctx.call(body, BigDecimal.valueOf(i));
        }
        return self;
    }

    @Op("collect:")
    static PArray collect(CallContext ctx, BigDecimal self, Block body) {
        long n = count(self);
        PArray out = new PArray();
        for (long i = 0; i < n; i++) {
            out.add(ctx.call(body, BigDecimal.valueOf(i)));
        }
        return out;
    }

    /** A whole number in [0, receiver), from the cell's random source. */
    @Op("random")
    static BigDecimal random(CallContext ctx, BigDecimal self) {
        long n = count(self);
        if (n <= 0) {
            throw new PonderError("random needs a positive number, got " + self);
        }
        return BigDecimal.valueOf(ctx.runtime().random().nextLong(n));
    }

    /** How many times a loop over {@code n} runs: its ceiling, 0 when not positive, at most Long.MAX_VALUE. */
    private static long count(BigDecimal n) {
        if (n.signum() <= 0) {
            return 0;
        }
        if (Numbers.wholeDigits(n) <= 0) {
            return 1;   // a positive number below 1: rounding 1e-400000000 up would write out its digits
        }
        if (Numbers.wholeDigits(n) > 19) {
            return Long.MAX_VALUE;   // beyond a long; rounding it first would write out all its digits
        }
        try {
            return n.setScale(0, java.math.RoundingMode.CEILING).longValueExact();
        } catch (ArithmeticException e) {
            return Long.MAX_VALUE;
        }
    }
}
