package net.smc.policy.runtime;

import net.smc.policy.api.Nil;
import net.smc.policy.api.PonderError;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.api.OpInterfaces;
import java.lang.reflect.Constructor;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.math.BigDecimal;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The dispatch table of one kind of PonderTalk object, built once per Java class from its
 * {@link Op} annotations (on the class, its superclasses and, for instance operations, the
 * interfaces it implements): selector to {@link Operation}. Every table also answers {@code class},
 * {@code self}, {@code ==} and {@code !=}, except nil's, which answers nothing.
 */
public final class ManagedClass {
    private static final ClassValue<ManagedClass> MANAGED = new ClassValue<>() {
        @Override
        protected ManagedClass computeValue(Class<?> type) {
            return build(displayName(type), type, Operation.Kind.INSTANCE, false);
        }
    };
    private static final ClassValue<ManagedClass> FACTORIES = new ClassValue<>() {
        @Override
        protected ManagedClass computeValue(Class<?> type) {
            return build("Factory", type, Operation.Kind.FACTORY, true);
        }
    };
    private static final Map<String, Operation> COMMON = operations(ObjectOps.class, Operation.Kind.STATIC_RECEIVER, "Object");

    static final ManagedClass NUMBER = values("Number", NumberOps.class);
    static final ManagedClass STRING = values("String", StringOps.class);
    static final ManagedClass BOOLEAN = values("Boolean", BooleanOps.class);
    static final ManagedClass NIL = new ManagedClass("nil", Nil.class, Map.of(), false);

    private final String name;
    private final Class<?> javaClass;
    private final Map<String, Operation> ops;
    private final boolean factory;

    private ManagedClass(String name, Class<?> javaClass, Map<String, Operation> ops, boolean factory) {
        this.name = name;
        this.javaClass = javaClass;
        this.ops = ops;
        this.factory = factory;
    }

    /**
     * The table of a managed-object class (or of a value class such as {@link PArray}): its
     * instance operations. Checks every annotation; a wrong arity is an
     * {@link IllegalArgumentException} naming the method.
     */
    public static ManagedClass of(Class<?> type) {
        return MANAGED.get(type);
    }

    /** The table of a class's factory: its annotated constructors and static methods. */
    public static ManagedClass factoryOf(Class<?> type) {
        return FACTORIES.get(type);
    }

    /** The table for any PonderTalk value. */
    static ManagedClass typeOf(Object value) {
        if (value instanceof ManagedObject m) {
            return m.type();
        }
        if (value instanceof BigDecimal) {
            return NUMBER;
        }
        if (value instanceof String) {
            return STRING;
        }
        if (value instanceof Boolean) {
            return BOOLEAN;
        }
        if (value instanceof Nil) {
            return NIL;
        }
        return MANAGED.get(value.getClass());
    }

    /** How PonderTalk names a Java class: its {@link Managed} name, else its simple name. */
    static String displayName(Class<?> type) {
        Managed named = type.getAnnotation(Managed.class);
        return named != null ? named.value() : type.getSimpleName();
    }

    private static ManagedClass values(String name, Class<?> holder) {
        return new ManagedClass(name, holder, withCommon(operations(holder, Operation.Kind.STATIC_RECEIVER, name)), false);
    }

    private static ManagedClass build(String name, Class<?> type, Operation.Kind kind, boolean factory) {
        Map<String, Operation> ops = operations(type, kind, factory ? name + " of " + displayName(type) : name);
        return new ManagedClass(name, type, withCommon(ops), factory);
    }

    private static Map<String, Operation> withCommon(Map<String, Operation> own) {
        Map<String, Operation> all = new HashMap<>(COMMON);
        all.putAll(own);
        return Map.copyOf(all);
    }

    private static Map<String, Operation> operations(Class<?> type, Operation.Kind kind, String owner) {
        Map<String, Operation> ops = new HashMap<>();
        if (kind == Operation.Kind.FACTORY) {
            for (Constructor<?> c : type.getDeclaredConstructors()) {
                Op op = c.getAnnotation(Op.class);
                if (op != null) {
                    put(ops, op.value(), Operation.of(op.value(), c, kind, owner), type);
                }
            }
        }
        for (Class<?> k = type; k != null && k != Object.class; k = k.getSuperclass()) {
            // A subclass's operation overrides its superclass's; two in one class are an error.
            Set<String> inherited = k == type ? Set.of() : Set.copyOf(ops.keySet());
            for (Method m : k.getDeclaredMethods()) {
                Op op = m.getAnnotation(Op.class);
                if (op == null || m.isBridge()) {
                    continue;
                }
                boolean isStatic = Modifier.isStatic(m.getModifiers());
                boolean wanted = switch (kind) {
                    case INSTANCE -> !isStatic;
                    case STATIC_RECEIVER, FACTORY -> isStatic;
                };
                if (wanted && !inherited.contains(op.value())) {
                    put(ops, op.value(), Operation.of(op.value(), m, kind, owner), type);
                }
            }
            if (kind != Operation.Kind.INSTANCE) {
                break;
            }
        }
        if (kind == Operation.Kind.INSTANCE) {
            interfaceOperations(type, ops, owner);
        }
        return ops;
    }

    /**
     * Adds the {@link Op}s declared on the interfaces the class implements (its own, its
     * superclasses', and theirs), so that an interface can define a managed object's operations
     * (the core's task interfaces do). A selector the class chain defines wins over every
     * interface's; between interfaces, one that extends another wins over it; the same selector from
     * two unrelated interfaces is an error, since neither is more specific.
     */
    private static void interfaceOperations(Class<?> type, Map<String, Operation> ops, String owner) {
        Set<String> fromClasses = Set.copyOf(ops.keySet());
        Map<String, Class<?>> declaredBy = new HashMap<>();
        for (Class<?> i : interfacesOf(type)) {
            for (Method m : i.getDeclaredMethods()) {
                Op op = m.getAnnotation(Op.class);
                if (op == null || m.isBridge() || m.isSynthetic() || Modifier.isStatic(m.getModifiers())
                        || fromClasses.contains(op.value())) {
                    continue;
                }
                Class<?> earlier = declaredBy.get(op.value());
                if (earlier == null || (earlier != i && earlier.isAssignableFrom(i))) {
                    ops.put(op.value(), Operation.of(op.value(), m, Operation.Kind.INSTANCE, owner));
                    declaredBy.put(op.value(), i);
                } else if (earlier == i) {
                    throw new IllegalArgumentException("selector '" + op.value() + "' is defined twice in " + i.getName());
                } else if (!i.isAssignableFrom(earlier)) {
                    throw new IllegalArgumentException("selector '" + op.value() + "' of " + type.getName()
                            + " is defined by both " + earlier.getName() + " and " + i.getName()
                            + "; define it on the class to choose");
                }
            }
        }
    }

    /** Every interface a class implements, directly or through superclasses and superinterfaces, nearest first. */
    static Set<Class<?>> interfacesOf(Class<?> type) {
        return OpInterfaces.of(type);
    }

    /**
     * The table of a {@code base} (a domain, say) that also answers the instance operations of the
     * Java object {@code extension}, which win over the base's and run on the extension; named after
     * the extension's class, as if that class extended the base.
     */
    static ManagedClass withOperationsOf(Class<?> base, Object extension) {
        String name = displayName(extension.getClass());
        ExtendedTables tables = EXTENDED.computeIfAbsent(List.of(base, extension.getClass()), k -> new ExtendedTables(
                Map.copyOf(operations(base, Operation.Kind.INSTANCE, name)),
                Map.copyOf(operations(extension.getClass(), Operation.Kind.INSTANCE, name))));
        Map<String, Operation> ops = new HashMap<>(tables.base());
        tables.extension().forEach((selector, op) -> ops.put(selector, op.boundTo(extension)));
        return new ManagedClass(name, extension.getClass(), withCommon(ops), false);
    }

    /**
     * The operations of a base class and of an extension's class, not yet bound to an extension: read
     * from the annotations once per pair of classes (a cell makes such a domain for every role it loads).
     */
    private record ExtendedTables(Map<String, Operation> base, Map<String, Operation> extension) {
    }

    private static final Map<List<Class<?>>, ExtendedTables> EXTENDED = new ConcurrentHashMap<>();

    private static void put(Map<String, Operation> ops, String selector, Operation op, Class<?> type) {
        if (ops.putIfAbsent(selector, op) != null) {
            throw new IllegalArgumentException("selector '" + selector + "' is defined twice in " + type.getName());
        }
    }

    /** The operation for a selector, or {@code null}. */
    Operation lookup(String selector) {
        return ops.get(selector);
    }

    /** The error for a selector this class does not understand. */
    PonderError unknown(String selector) {
        if (factory) {
            return new PonderError("unknown constructor or static operation: '" + selector + "'");
        }
        return new PonderError("unknown operation '" + selector + "' on " + name);
    }

    /** The class name PonderTalk shows. */
    public String name() {
        return name;
    }

    public Class<?> javaClass() {
        return javaClass;
    }

    public boolean isFactory() {
        return factory;
    }

    /** The selectors this class answers, sorted. */
    public Set<String> selectors() {
        return Collections.unmodifiableSet(new TreeSet<>(ops.keySet()));
    }

    @Override
    public String toString() {
        return name;
    }
}
