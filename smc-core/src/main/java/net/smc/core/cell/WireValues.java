package net.smc.core.cell;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import net.smc.policy.api.Nil;
import net.smc.policy.api.ArrayValue;
import net.smc.policy.api.HashValue;

/**
 * Java and PonderTalk values as the values messages carry (String, BigDecimal, Boolean, null and
 * lists of them). A map becomes a list that starts with {@link #MAP} and alternates keys and values,
 * and comes back as a map; anything else (a managed object, a block) travels as its printed text.
 */
final class WireValues {
    /** The first element of a list that stands for a map. */
    static final String MAP = "#map";

    private WireValues() {
    }

    static Object of(Object v) {
        if (v == null || v instanceof Nil) {
            return null;
        }
        if (v instanceof String || v instanceof Boolean || v instanceof BigDecimal) {
            return v;
        }
        if (v instanceof Double || v instanceof Float) {
            double d = ((Number) v).doubleValue();
            return Double.isFinite(d) ? BigDecimal.valueOf(d) : String.valueOf(d);
        }
        if (v instanceof Number n) {
            return new BigDecimal(n.toString());
        }
        if (v instanceof ArrayValue a) {
            return list(a.items());
        }
        if (v instanceof Collection<?> c) {
            return list(c);
        }
        if (v instanceof Object[] array) {
            return list(List.of(array));
        }
        if (v instanceof HashValue h) {
            Map<Object, Object> m = new LinkedHashMap<>();
            h.entries().forEach(e -> m.put(e.getKey(), e.getValue()));
            return map(m);
        }
        if (v instanceof Map<?, ?> m) {
            return map(m);
        }
        return net.smc.policy.PolicyEngine.print(v);
    }

    /** A list of wire values, each element converted by {@link #of}. */
    static List<Object> list(Collection<?> values) {
        List<Object> out = new ArrayList<>(values.size());
        for (Object o : values) {
            out.add(of(o));
        }
        return out;
    }

    private static List<Object> map(Map<?, ?> m) {
        List<Object> out = new ArrayList<>();
        out.add(MAP);
        m.forEach((k, val) -> {
            out.add(String.valueOf(k));
            out.add(of(val));
        });
        return out;
    }

    /** The Java form of a wire value: lists that stand for maps become maps again. */
    static Object toJava(Object v) {
        if (v instanceof List<?> l) {
            if (!l.isEmpty() && MAP.equals(l.get(0))) {
                Map<String, Object> m = new LinkedHashMap<>();
                for (int i = 1; i + 1 < l.size(); i += 2) {
                    m.put(String.valueOf(l.get(i)), toJava(l.get(i + 1)));
                }
                return m;
            }
            List<Object> out = new ArrayList<>(l.size());
            l.forEach(o -> out.add(toJava(o)));
            return out;
        }
        return v;
    }
}
