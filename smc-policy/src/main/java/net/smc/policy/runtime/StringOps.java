package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;
import net.smc.policy.api.Op;
import java.math.BigDecimal;

/** Operations of strings. */
final class StringOps {
    /** Longest string {@code *} builds, in characters. */
    static final int MAX_REPEAT_LENGTH = 64 * 1024 * 1024;

    private StringOps() {
    }

    /** Concatenates the argument's printed form. */
    @Op("+")
    static String concat(CallContext ctx, String self, Object other) {
        String tail = Values.print(other);
        long length = (long) self.length() + tail.length();
        if (length > MAX_REPEAT_LENGTH) {
            throw new PonderError("string longer than " + MAX_REPEAT_LENGTH + " characters");
        }
        ctx.execution().charge(length, "String +");
        return self + tail;
    }

    @Op("*")
    static String repeat(CallContext ctx, String self, BigDecimal times) {
        Integer n = Numbers.intValue(times);
        if (n == null || n < 0) {
            throw new PonderError("cannot repeat a string " + times + " times");
        }
        if ((long) self.length() * n > MAX_REPEAT_LENGTH) {
            throw new PonderError("string longer than " + MAX_REPEAT_LENGTH + " characters");
        }
        ctx.execution().charge((long) self.length() * n, "String *");
        return self.repeat(n);
    }

    @Op("asString")
    static String asString(String self) {
        return self;
    }

    @Op("isEmpty")
    static boolean isEmpty(String self) {
        return self.isEmpty();
    }

    /** Parses the string as XML (with the parser the engine was configured with: the standard objects' XML value). */
    @Op("asXML")
    static Object asXML(CallContext ctx, String self) {
        return ctx.runtime().parseXml(self);
    }

    /** Resolves the string as a path: absolute when it starts with '/', else from root. */
    @Op("asObject")
    static Object asObject(CallContext ctx, String self) {
        return ctx.runtime().resolve(self);
    }
}
