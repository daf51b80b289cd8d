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

    /**
     * The digits a number has before its decimal point (negative for a number below 0.1: -2 for
     * 0.001); 0 for zero.
     */
    static long wholeDigits(BigDecimal n) {
        return n.signum() == 0 ? 0 : (long) n.precision() - n.scale();
    }

    /**
     * Refuses a sum or difference of {@code a} and {@code b} whose exact result would have more
     * than {@link #MAX_DIGITS} digits, before computing it: {@code 1e100000000 + 1} has a hundred
     * million, and working them out would hold the cell's thread for minutes.
     */
    private static void checkSum(BigDecimal a, BigDecimal b) {
        if (a.signum() == 0 && b.signum() == 0) {
            return;   // zero, at once
        }
        // a zero adds no digits before the point, but its scale counts (1 + 0E-400000000 has 400000001)
        long highest = a.signum() == 0 ? wholeDigits(b) : b.signum() == 0 ? wholeDigits(a) : Math.max(wholeDigits(a), wholeDigits(b));
        long lowest = Math.max(a.scale(), b.scale());   // digits after the point the result keeps
        // the result has highest + lowest digits, or one more for a carry, which checked() sees
        if (highest + lowest > MAX_DIGITS) {
            throw new PonderError("number overflow");
        }
    }

    public static BigDecimal add(BigDecimal a, BigDecimal b) {
        checkSum(a, b);
        try {
            return checked(a.add(b));
        } catch (ArithmeticException e) {
            throw new PonderError("number overflow");
        }
    }

    public static BigDecimal subtract(BigDecimal a, BigDecimal b) {
        checkSum(a, b);
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

    /**
     * Division as Ponder2: {@code divide(x, 5, HALF_UP)}. A quotient below 0.000001 is 0.00000
     * without computing it, and one with more than {@link #MAX_DIGITS} digits is refused: either
     * would otherwise take a power of ten as large as the exponents apart ({@code 1 / 3e-400000000}).
     */
    public static BigDecimal divide(BigDecimal a, BigDecimal b) {
        if (b.signum() == 0) {
            throw new PonderError("division by zero");
        }
        long quotientDigits = wholeDigits(a) - wholeDigits(b) + 1;   // |a / b| < 10^quotientDigits
        if (a.signum() == 0 || quotientDigits <= -6) {
            return BigDecimal.ZERO.setScale(5);
        }
        if (quotientDigits - 1 + 5 > MAX_DIGITS) {   // at least that many digits; checked() sees the one more
            throw new PonderError("number overflow");
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
