package net.smc.policy.runtime;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * The variables of one unit or one block call. A block call sees the values its block captured
 * when it was created (only the names its code reads, frozen then) plus its own parameters and
 * assignments, which vanish with the call. A unit sees the variables a shell session kept plus its
 * own. Names are interned by the compiler, so lookups compare references.
 */
final class VariableFrame {
    private static final int SMALL = 16;
    private static final String[] NONE = new String[0];

    final Execution ex;
    private final String[] capturedNames;
    private final Object[] capturedValues;
    private final Map<String, Object> outer;
    private String[] names;
    private Object[] values;
    private int count;
    private HashMap<String, Object> many;

    /** A unit's frame; {@code outer} holds a session's kept variables (read-only here). */
    VariableFrame(Execution ex, Map<String, Object> outer) {
        this.ex = ex;
        this.capturedNames = NONE;
        this.capturedValues = null;
        this.outer = outer;
        this.names = new String[4];
        this.values = new Object[4];
    }

    /** A block call's frame; {@code params} is shared and never changed. */
    VariableFrame(Execution ex, String[] capturedNames, Object[] capturedValues, String[] params, Object[] args) {
        this.ex = ex;
        this.capturedNames = capturedNames;
        this.capturedValues = capturedValues;
        this.outer = Map.of();
        this.names = params;
        this.values = args.length == params.length ? args : Arrays.copyOf(args, params.length);
        this.count = params.length;
    }

    /** The variable's value, or {@code null} when there is no such variable. */
    Object lookup(String name) {
        if (many != null) {
            Object v = many.get(name);
            if (v != null) {
                return v;
            }
        } else {
            for (int i = count - 1; i >= 0; i--) {
                if (names[i] == name) {
                    return values[i];
                }
            }
        }
        for (int i = 0; i < capturedNames.length; i++) {
            if (capturedNames[i] == name) {
                return capturedValues[i];
            }
        }
        return outer.isEmpty() ? null : outer.get(name);
    }

    void set(String name, Object value) {
        if (many != null) {
            many.put(name, value);
            return;
        }
        for (int i = 0; i < count; i++) {
            if (names[i] == name) {
                values[i] = value;
                return;
            }
        }
        if (count == SMALL) {
            many = new HashMap<>();
            for (int i = 0; i < count; i++) {
                many.put(names[i], values[i]);
            }
            many.put(name, value);
            return;
        }
        if (count == names.length) {
            names = Arrays.copyOf(names, Math.max(4, count * 2));
            values = Arrays.copyOf(values, names.length);
        }
        names[count] = name;
        values[count] = value;
        count++;
    }

    /** The current values of {@code free} (null where a name is not a variable), for a new block. */
    Object[] capture(String[] free) {
        Object[] captured = new Object[free.length];
        for (int i = 0; i < free.length; i++) {
            captured[i] = lookup(free[i]);
        }
        return captured;
    }

    /** The unit's own variables (for a shell session that keeps them across inputs). */
    Map<String, Object> locals() {
        if (many != null) {
            return new HashMap<>(many);
        }
        HashMap<String, Object> out = new HashMap<>();
        for (int i = 0; i < count; i++) {
            out.put(names[i], values[i]);
        }
        return out;
    }
}
