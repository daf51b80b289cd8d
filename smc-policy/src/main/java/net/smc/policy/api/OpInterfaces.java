package net.smc.policy.api;

import java.util.ArrayDeque;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * The interfaces whose {@link Op} methods a managed object answers besides its class's: every
 * interface its class implements, directly or through superclasses and superinterfaces.
 */
public final class OpInterfaces {
    private OpInterfaces() {
    }

    /** Every interface {@code type} implements, nearest first (its own, then its superclasses', then theirs). */
    public static Set<Class<?>> of(Class<?> type) {
        Set<Class<?>> found = new LinkedHashSet<>();
        ArrayDeque<Class<?>> queue = new ArrayDeque<>();
        for (Class<?> k = type; k != null; k = k.getSuperclass()) {
            queue.addAll(List.of(k.getInterfaces()));
        }
        while (!queue.isEmpty()) {
            Class<?> i = queue.removeFirst();
            if (found.add(i)) {
                queue.addAll(List.of(i.getInterfaces()));
            }
        }
        return found;
    }
}
