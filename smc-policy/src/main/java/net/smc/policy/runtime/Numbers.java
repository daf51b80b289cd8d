package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;
import java.math.BigDecimal;
import java.math.RoundingMode;

/** Number conversions and arithmetic with PonderTalk's error messages. */
public final class Numbers {
    /** Largest length of a string that is parsed as a number; longer strings are refused. */
    private static final int MAX_PARSE_LENGTH = 1000;
    /** Results whose unscaled value grows beyond this many digits are refused (a bounded cost per operation). */
    private static final int MAX_DIGITS = 10_000;

    private Numbers() {
    }

    /** Parses a string as a number, or answers {@code null}. */
    public static BigDecimal tryParse(String s) {
        String t = s.trim();
        if (t.isEmpty() || t.length() > MAX_PARSE_LENGTH) {
            return null;
        }
        try {
            return new BigDecimal(t);
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /** Converts an argument to a number: numbers as they are, strings parsed, anything else refused. */
    public static BigDecimal toNumber(Object v) {
        if (v instanceof BigDecimal n) {
            return n;
        }
        if (v instanceof String s) {
            BigDecimal n = tryParse(s);
            if (n == null) {
                throw new PonderError("cannot parse '" + abbreviate(s) + "' as a number");
            }
            return n;
        }
        throw new PonderError("not a number: " + abbreviate(Values.print(v)));
    }

    static String abbreviate(String s) {
        return s.length() > 60 ? s.substring(0, 57) + "..." : s;
    }

    static BigDecimal checked(BigDecimal r) {
        if (r.precision() > MAX_DIGITS) {
            throw new PonderError("number overflow");
        }
        return r;
    }

    public static BigDecimal add(BigDecimal a, BigDecimal b) {
        try {
            return checked(a.add(b));
        } catch (ArithmeticException e) {
            throw new PonderError("number overflow");
        }
    }

    public static BigDecimal subtract(BigDecimal a, BigDecimal b) {
        try {
            return checked(a.subtract(b));
        } catch (ArithmeticException e) {
            throw new PonderError("number overflow");
        }
    }

    public static BigDecimal multiply(BigDecimal a, BigDecimal b) {
        try {
            if ((long) a.precision() + b.precision() > MAX_DIGITS) {
                throw new PonderError("number overflow");
            }
            return a.multiply(b);
        } catch (ArithmeticException e) {
            throw new PonderError("number overflow");
        }
    }

    /** Division as Ponder2: {@code divide(x, 5, HALF_UP)}. */
    public static BigDecimal divide(BigDecimal a, BigDecimal b) {
        if (b.signum() == 0) {
            throw new PonderError("division by zero");
        }
        try {
            return checked(a.divide(b, 5, RoundingMode.HALF_UP));
        } catch (ArithmeticException e) {
            throw new PonderError("number overflow");
        }
    }

    /** A whole number that fits an int, or {@code null}. */
    public static Integer intValue(BigDecimal n) {
        try {
            return n.intValueExact();
        } catch (ArithmeticException e) {
            try {
                BigDecimal stripped = n.stripTrailingZeros();
                return stripped.scale() <= 0 ? stripped.intValueExact() : null;
            } catch (ArithmeticException e2) {
                return null;
            }
        }
    }

}
