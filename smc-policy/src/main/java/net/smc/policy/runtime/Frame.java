package net.smc.policy.runtime;

import java.util.HashMap;
import java.util.Map;

/**
 * The variables of one unit or one block call: the bindings captured when the block was created
 * (read-only, shared by every call) plus this call's own (parameters and assignments), which
 * vanish with the call. Names are interned by the compiler, so lookups mostly compare references.
 */
final class Frame {
    private static final int SMALL = 16;

    final Execution ex;
    private final Map<String, Object> captured;
    private String[] names;
    private Object[] values;
    private int count;
    private HashMap<String, Object> many;

    Frame(Execution ex, Map<String, Object> captured) {
        this.ex = ex;
        this.captured = captured;
        this.names = new String[4];
        this.values = new Object[4];
    }

    /** A block call's frame; {@code params} is not copied and must not be changed. */
    Frame(Execution ex, Map<String, Object> captured, String[] params, Object[] args) {
        this.ex = ex;
        this.captured = captured;
        this.names = params;
        this.values = args.length == params.length ? args : java.util.Arrays.copyOf(args, params.length);
        this.count = params.length;
    }

    Object lookup(String name) {
        if (many != null) {
            Object v = many.get(name);
            return v != null ? v : captured.get(name);
        }
        for (int i = count - 1; i >= 0; i--) {
            if (names[i] == name) {
                return values[i];
            }
        }
        for (int i = count - 1; i >= 0; i--) {
            if (names[i].equals(name)) {
                return values[i];
            }
        }
        return captured.isEmpty() ? null : captured.get(name);
    }

    void set(String name, Object value) {
        if (many != null) {
            many.put(name, value);
            return;
        }
        for (int i = 0; i < count; i++) {
            if (names[i] == name || names[i].equals(name)) {
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
            names = java.util.Arrays.copyOf(names, Math.max(4, count * 2));
            values = java.util.Arrays.copyOf(values, names.length);
        }
        names[count] = name;
        values[count] = value;
        count++;
    }

    /** The bindings a block created now captures: everything visible, frozen. */
    Map<String, Object> snapshot() {
        if (count == 0 && many == null) {
            return captured;
        }
        HashMap<String, Object> all = new HashMap<>(captured);
        if (many != null) {
            all.putAll(many);
        } else {
            for (int i = 0; i < count; i++) {
                all.put(names[i], values[i]);
            }
        }
        return all;
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
