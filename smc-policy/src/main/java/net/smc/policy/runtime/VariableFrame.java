package net.smc.policy.runtime;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The variables of one unit or one block call. A block call sees the values its block captured
 * when it was created (only the names its code reads, frozen then) plus its own parameters and
 * assignments, which vanish with the call. A unit sees the variables a shell session kept plus its
 * own. Names are interned by the compiler, so lookups compare references.
 *
 * <p>The name {@code Variables}, unless assigned, answers these variables as a hash (as Ponder2):
 * the first time it is asked for, every visible variable moves into that hash, which from then on
 * is the frame's only store, so assignments show in the hash and {@code at:put:} and
 * {@code remove:} on it change the variables.
 */
final class VariableFrame {
    /** The name that answers the frame's variables as a hash. */
    static final String VARIABLES = "Variables";

    private static final int SMALL = 16;
    private static final String[] NONE = new String[0];

    final Execution ex;
    private final String[] capturedNames;
    private final Object[] capturedValues;
    private final Map<String, Object> outer;
    private String[] names;
    private Object[] values;
    private int count;
    private LinkedHashMap<String, Object> many;
    private PHash hash;

    /** A unit's frame; {@code outer} holds a session's kept variables (read-only here). */
    VariableFrame(Execution ex, Map<String, Object> outer) {
        this.ex = ex;
        this.capturedNames = NONE;
        this.capturedValues = null;
        this.outer = outer;
        this.names = new String[4];
        this.values = new Object[4];
    }

    /**
     * A block call's frame; {@code params} is shared and never changed. {@code scope} is every
     * variable seen where the block was made, for a block that reads {@code Variables} (else empty).
     */
    VariableFrame(Execution ex, String[] capturedNames, Object[] capturedValues, String[] params, Object[] args,
            Map<String, Object> scope) {
        this.ex = ex;
        this.capturedNames = capturedNames;
        this.capturedValues = capturedValues;
        this.outer = scope;
        this.names = params;
        this.values = args.length == params.length ? args : Arrays.copyOf(args, params.length);
        this.count = params.length;
    }

    /** The variable's value, or {@code null} when there is no such variable. */
    Object lookup(String name) {
        if (hash != null) {
            return hash.get(name);
        }
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
        if (hash != null) {
            hash.put(name, value);
            return;
        }
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
            many = new LinkedHashMap<>();
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

    /**
     * The frame's variables as a hash ({@code Variables}); made on first use from every visible
     * variable (a session's kept ones, captured ones, then this frame's own, in that order).
     */
    PHash variables() {
        if (hash == null) {
            hash = new PHash(visible());
        }
        return hash;
    }

    /** Every variable this frame sees, by name, in the order {@link #variables()} lists them. */
    private Map<String, Object> visible() {
        if (hash != null) {
            return new LinkedHashMap<>(hash.asMap());
        }
        LinkedHashMap<String, Object> all = new LinkedHashMap<>(outer);
        for (int i = 0; i < capturedNames.length; i++) {
            if (capturedValues[i] != null) {
                all.put(capturedNames[i], capturedValues[i]);
            }
        }
        all.putAll(locals());
        return all;
    }

    /**
     * The current values of {@code free} (null where a name is not a variable), for a new block. A
     * block never captures {@code Variables}: in each call that name is the call's own hash.
     */
    Object[] capture(String[] free) {
        Object[] captured = new Object[free.length];
        for (int i = 0; i < free.length; i++) {
            captured[i] = free[i] == VARIABLES ? null : lookup(free[i]);
        }
        return captured;
    }

    /** Every visible variable but {@code Variables} (names interned), for a block that reads the hash. */
    Map<String, Object> snapshot() {
        Map<String, Object> all = new LinkedHashMap<>();
        visible().forEach((name, value) -> {
            if (!name.equals(VARIABLES)) {
                all.put(name.intern(), value);
            }
        });
        return all;
    }

    /** The variables a shell session keeps after this unit: all of them once the hash was used. */
    Map<String, Object> kept() {
        return visible();
    }

    /** The unit's own variables (for a shell session that keeps them across inputs). */
    Map<String, Object> locals() {
        if (many != null) {
            return new LinkedHashMap<>(many);
        }
        LinkedHashMap<String, Object> out = new LinkedHashMap<>();
        for (int i = 0; i < count; i++) {
            out.put(names[i], values[i]);
        }
        return out;
    }
}
