package net.smc.policy.runtime;

import net.smc.policy.api.Nil;
import java.math.BigDecimal;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.Set;

/** Printing, equality and class names of PonderTalk values: one place for the rules of smc-policy/PONDERTALK.md section 5. */
public final class Values {
    private Values() {
    }

    /**
     * The printed form of a value, as {@code root print:} shows it. An array or hash inside itself
     * (a unit's {@code Variables} held in one of its variables, say) prints there as {@code ...}.
     */
    public static String print(Object value) {
        if (value instanceof PArray || value instanceof PHash) {
            StringBuilder out = new StringBuilder();
            printContainer(value, out, Collections.newSetFromMap(new IdentityHashMap<>()));
            return out.toString();
        }
        return printScalar(value);
    }

    private static String printScalar(Object value) {
        if (value instanceof String s) {
            return s;
        }
        if (value instanceof BigDecimal n) {
            return n.toString();
        }
        return String.valueOf(value);
    }

    private static void printInto(Object value, StringBuilder out, Set<Object> open) {
        if (value instanceof PArray || value instanceof PHash) {
            if (open.contains(value)) {
                out.append("...");
            } else {
                printContainer(value, out, open);
            }
        } else {
            out.append(printScalar(value));
        }
    }

    private static void printContainer(Object value, StringBuilder out, Set<Object> open) {
        open.add(value);
        if (value instanceof PArray a) {
            out.append('[');
            for (int i = 0; i < a.size(); i++) {
                if (i > 0) {
                    out.append(", ");
                }
                printInto(a.get(i), out, open);
            }
            out.append(']');
        } else {
            out.append("{ ");
            for (Map.Entry<String, Object> e : ((PHash) value).entries()) {
                out.append(e.getKey()).append("=\"");
                printInto(e.getValue(), out, open);
                out.append("\" ");
            }
            out.append('}');
        }
        open.remove(value);
    }

    /** PonderTalk's class name of a value. */
    public static String className(Object value) {
        if (value instanceof BigDecimal) {
            return "Number";
        }
        if (value instanceof String) {
            return "String";
        }
        if (value instanceof Boolean) {
            return "Boolean";
        }
        if (value instanceof PArray) {
            return "Array";
        }
        if (value instanceof PHash) {
            return "Hash";
        }
        if (value instanceof Block) {
            return "Block";
        }
        if (value instanceof Nil) {
            return "nil";
        }
        if (value instanceof ManagedObject m) {
            return m.type().name();
        }
        if (value instanceof ErrorValue) {
            return "Error";
        }
        return value.getClass().getSimpleName();
    }

    /**
     * {@code ==}: value equality for numbers (numerically), strings and booleans; identity for
     * everything else. A string equals a non-string by the other's printed form, whichever side it
     * is on ({@code true == "true"} as {@code "true" == true}).
     */
    public static boolean same(Object a, Object b) {
        if (a == b) {
            return true;
        }
        if (a instanceof BigDecimal x) {
            if (b instanceof BigDecimal y) {
                return x.compareTo(y) == 0;
            }
            if (b instanceof String s) {
                BigDecimal y = Numbers.tryParse(s);
                return y != null && x.compareTo(y) == 0;
            }
            return false;
        }
        if (a instanceof String s) {
            return s.equals(print(b));
        }
        if (a instanceof Boolean) {
            return a.equals(b) || b instanceof String s && s.equals(print(a));   // as "true" == true
        }
        return false;
    }

    /** Whether a value is a plain value (never checked by authorisation, never in a domain's parent lists). */
    public static boolean isValue(Object v) {
        return !(v instanceof ManagedObject);
    }

    /**
     * A value as an error message shows it: its printed form (shortened), a string quoted and named
     * as one, so that {@code "true"} is not taken for the boolean.
     */
    static String describe(Object value) {
        String printed = Numbers.abbreviate(print(value));
        return value instanceof String ? "'" + printed + "' (a String)" : printed;
    }

    /** A class name with its indefinite article: {@code a String}, {@code an EventTemplate}. */
    static String withArticle(String name) {
        return (!name.isEmpty() && "AEIOUaeiou".indexOf(name.charAt(0)) >= 0 ? "an " : "a ") + name;
    }
}
