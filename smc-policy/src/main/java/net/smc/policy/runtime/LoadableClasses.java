package net.smc.policy.runtime;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import net.smc.policy.api.PonderError;

/**
 * The classes a cell can load with {@code root load: "name"}: the built-in kinds (domains, event
 * templates, obligation and authorisation policies, date-times) and those the embedder registers,
 * each checked when registered, and each one's factory object, made on its first load.
 */
final class LoadableClasses {
    private final Map<String, Class<?>> registry = new LinkedHashMap<>();
    private final Map<String, ManagedObject> factories = new HashMap<>();

    LoadableClasses() {
        registry.put("Domain", Domain.class);
        registry.put("EventTemplate", EventTemplate.class);
        registry.put("ObligationPolicy", ObligationPolicy.class);
        registry.put("AuthorisationPolicy", AuthorisationPolicy.class);
        registry.put("DateTime", DateTime.class);
    }

    /** A new factory object of a managed class. */
    static ManagedObject factoryFor(Class<?> type) {
        return new ManagedObject(type, ManagedClass.factoryOf(type));
    }

    /** Makes a class loadable as {@code name}; checks its annotations now. */
    void register(String name, Class<?> type) {
        ManagedClass.of(type);
        ManagedClass.factoryOf(type);
        registry.put(name, type);
        factories.remove(name);
    }

    /** The factory of a registered class. */
    ManagedObject load(String name) {
        Class<?> type = registry.get(name);
        if (type == null) {
            throw new PonderError("Load Managed Object - Adaptor for '" + name + "' not found; loadable: "
                    + String.join(", ", names()));
        }
        return factories.computeIfAbsent(name, n -> factoryFor(type));
    }

    /** The loadable names, sorted. */
    Set<String> names() {
        return new TreeSet<>(registry.keySet());
    }
}
