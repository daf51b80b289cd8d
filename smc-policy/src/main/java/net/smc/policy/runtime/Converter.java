package net.smc.policy.runtime;

import net.smc.policy.api.ArrayValue;
import net.smc.policy.api.HashValue;
import net.smc.policy.api.Nil;
import net.smc.policy.api.PonderError;
import java.math.BigDecimal;
import java.util.Collection;
import java.util.Map;

/** Converts a PonderTalk argument to a Java parameter's declared type, and Java results back. */
@FunctionalInterface
interface Converter {

    Object convert(Object value);

    /** The converter for a parameter, or {@code null} when the value passes as it is. */
    static Converter forType(Class<?> type, int position, String selector, String owner) {
        if (type == Object.class) {
            return null;
        }
        if (type == String.class) {
            return v -> {
                if (v instanceof String) {
                    return v;
                }
                if (v instanceof BigDecimal || v instanceof Boolean) {
                    return Values.print(v);
                }
                throw mismatch(position, selector, owner, "String", v);
            };
        }
        if (type == BigDecimal.class || type == Number.class) {
            return Numbers::toNumber;
        }
        if (type == int.class || type == Integer.class) {
            return v -> {
                Integer i = Numbers.intValue(Numbers.toNumber(v));
                if (i == null) {
                    throw new PonderError("argument " + position + " of '" + selector + "' on " + owner
                            + " must be a whole number, got " + Numbers.abbreviate(Values.print(v)));
                }
                return i;
            };
        }
        if (type == long.class || type == Long.class) {
            return v -> {
                try {
                    return Numbers.toNumber(v).longValueExact();
                } catch (ArithmeticException e) {
                    throw new PonderError("argument " + position + " of '" + selector + "' on " + owner
                            + " must be a whole number, got " + Numbers.abbreviate(Values.print(v)));
                }
            };
        }
        if (type == double.class || type == Double.class) {
            return v -> Numbers.toNumber(v).doubleValue();
        }
        if (type == boolean.class || type == Boolean.class) {
            return v -> {
                if (v instanceof Boolean) {
                    return v;
                }
                throw new PonderError("not a boolean: " + Values.describe(v));
            };
        }
        if (type == Block.class) {
            return v -> {
                if (v instanceof Block) {
                    return v;
                }
                throw new PonderError("not a block: " + Numbers.abbreviate(Values.print(v)));
            };
        }
        if (ManagedObject.class.isAssignableFrom(type) || type.isInstance(Nil.NIL) || isValueType(type)) {
            return v -> {
                if (type.isInstance(v)) {
                    return v;
                }
                throw mismatch(position, selector, owner, ManagedClass.displayName(type), v);
            };
        }
        // A registered Java class: the argument is a managed object wrapping an instance of it.
        return v -> {
            if (v instanceof ManagedObject m && type.isInstance(m.impl())) {
                return m.impl();
            }
            if (type.isInstance(v)) {
                return v;
            }
            throw mismatch(position, selector, owner, ManagedClass.displayName(type), v);
        };
    }

    private static boolean isValueType(Class<?> type) {
        return type == PArray.class || type == PHash.class || type == ErrorValue.class
                || type == ArrayValue.class || type == HashValue.class;
    }

    private static PonderError mismatch(int position, String selector, String owner, String wanted, Object got) {
        return new PonderError("argument " + position + " of '" + selector + "' on " + owner + " must be "
                + Values.withArticle(wanted) + ", got " + Values.className(got));
    }

    /** Turns what a Java method returned into a PonderTalk value. */
    static Object fromJava(Object result) {
        if (result == null) {
            return Nil.NIL;
        }
        if (result instanceof BigDecimal || result instanceof String || result instanceof Boolean
                || result instanceof ManagedObject || result instanceof PArray || result instanceof PHash
                || result instanceof Block || result instanceof Nil || result instanceof ErrorValue) {
            return result;
        }
        if (result instanceof Integer || result instanceof Long || result instanceof Short || result instanceof Byte) {
            return BigDecimal.valueOf(((Number) result).longValue());
        }
        if (result instanceof Double || result instanceof Float) {
            double d = ((Number) result).doubleValue();
            if (Double.isNaN(d) || Double.isInfinite(d)) {
                throw new PonderError("the answer " + d + " is not a number PonderTalk can hold");
            }
            return BigDecimal.valueOf(d);
        }
        if (result instanceof java.math.BigInteger b) {
            return new BigDecimal(b);
        }
        if (result instanceof CharSequence cs) {
            return cs.toString();
        }
        if (result instanceof Collection<?> c) {
            PArray a = new PArray();
            for (Object o : c) {
                a.add(fromJava(o));
            }
            return a;
        }
        if (result instanceof Map<?, ?> m) {
            PHash h = new PHash();
            m.forEach((k, v) -> h.put(String.valueOf(k), fromJava(v)));
            return h;
        }
        return ManagedObject.wrap(result);
    }
}
