package net.smc.sim.task;

import java.util.List;
import java.util.Map;

/** Reads entries of handed-over state, with errors that name the task and the entry. */
final class StateValues {
    private StateValues() {
    }

    static boolean has(Map<String, ?> state, String key) {
        return state.get(key) != null;
    }

    static double number(String task, Map<String, ?> state, String key) {
        if (!(state.get(key) instanceof Number n) || !Double.isFinite(n.doubleValue())) {
            throw new IllegalArgumentException(task + " state: '" + key + "' must be a finite number, got "
                    + state.get(key));
        }
        return n.doubleValue();
    }

    static String string(String task, Map<String, ?> state, String key) {
        if (!(state.get(key) instanceof String s)) {
            throw new IllegalArgumentException(task + " state: '" + key + "' must be a string, got " + state.get(key));
        }
        return s;
    }

    static List<?> list(String task, Map<String, ?> state, String key) {
        if (!(state.get(key) instanceof List<?> l)) {
            throw new IllegalArgumentException(task + " state: '" + key + "' must be a list, got " + state.get(key));
        }
        return l;
    }

    @SuppressWarnings("unchecked")
    static Map<String, ?> map(String task, Map<String, ?> state, String key) {
        if (!(state.get(key) instanceof Map<?, ?> m)) {
            throw new IllegalArgumentException(task + " state: '" + key + "' must be a map, got " + state.get(key));
        }
        return (Map<String, ?>) m;
    }

    static double finite(String what, double value) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException(what + " " + value + " must be a finite number");
        }
        return value;
    }
}
