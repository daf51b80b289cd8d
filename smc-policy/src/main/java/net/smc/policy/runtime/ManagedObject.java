package net.smc.policy.runtime;

import net.smc.policy.api.Handle;
import net.smc.policy.api.Op;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A managed object: something that sits in domains, has policies attached and answers the
 * operations of its {@link ManagedClass}. Built-in kinds (domains, policies, event templates)
 * extend this class; any other annotated Java object is wrapped in one.
 */
public class ManagedObject implements Handle {
    private final Object impl;
    private final ManagedClass type;
    private final List<Domain> parents = new ArrayList<>(1);
    /** Obligation policies attached here, by the event template they react to, in attach order. */
    private Map<EventTemplate, ObligationPolicy[]> attached;
    /** Observers of every event that passes here (event forwarders), in the order they were added. */
    private List<EventObserver> observers;

    /** For subclasses: the object is its own implementation. */
    protected ManagedObject() {
        this.impl = this;
        this.type = ManagedClass.of(getClass());
    }

    /** For subclasses: the object is its own implementation, with the operations of {@code type}. */
    protected ManagedObject(ManagedClass type) {
        this.impl = this;
        this.type = type;
    }

    /** A handle for a Java object whose operations are given by {@code type}. */
    protected ManagedObject(Object impl, ManagedClass type) {
        this.impl = impl;
        this.type = type;
    }

    /** Wraps a Java object whose class carries {@link Op} annotations. */
    public static ManagedObject wrap(Object javaObject) {
        if (javaObject instanceof ManagedObject m) {
            return m;
        }
        return new ManagedObject(javaObject, ManagedClass.of(javaObject.getClass()));
    }

    /** The Java object whose methods implement the operations (this object for built-ins). */
    @Override
    public Object impl() {
        return impl;
    }

    public ManagedClass type() {
        return type;
    }

    @Override
    public String className() {
        return type.name();
    }

    @Override
    public Set<String> selectors() {
        return type.selectors();
    }

    /** The domains this object sits in, in the order it was added to them. */
    public List<Domain> parents() {
        return Collections.unmodifiableList(parents);
    }

    void addParent(Domain d) {
        if (!parents.contains(d)) {
            parents.add(d);
        }
    }

    void removeParent(Domain d) {
        parents.remove(d);
    }

    /** The first path from root to this object ({@code root/a/b}), or {@code null} if it is in no domain tree. */
    @Override
    public String path() {
        StringBuilder path = new StringBuilder();
        ManagedObject at = this;
        for (int hops = 0; hops < 64; hops++) {
            if (at instanceof Root) {
                path.insert(0, "root");
                return path.toString();
            }
            if (at.parents.isEmpty()) {
                return null;
            }
            Domain parent = at.parents.get(0);
            String name = parent.nameOf(at);
            if (name == null) {
                return null;
            }
            path.insert(0, "/" + name);
            at = parent;
        }
        return null;
    }

    void attach(ObligationPolicy policy) {
        if (attached == null) {
            attached = new HashMap<>();
        }
        ObligationPolicy[] list = attached.getOrDefault(policy.template(), NO_POLICIES);
        for (ObligationPolicy p : list) {
            if (p == policy) {
                return;
            }
        }
        int at = list.length;
        while (at > 0 && list[at - 1].attachOrder() > policy.attachOrder()) {
            at--;
        }
        ObligationPolicy[] grown = new ObligationPolicy[list.length + 1];
        System.arraycopy(list, 0, grown, 0, at);
        grown[at] = policy;
        System.arraycopy(list, at, grown, at + 1, list.length - at);
        attached.put(policy.template(), grown);
    }

    void detach(ObligationPolicy policy, EventTemplate template) {
        ObligationPolicy[] list = attached == null ? null : attached.get(template);
        if (list == null) {
            return;
        }
        ObligationPolicy[] kept = Arrays.stream(list).filter(p -> p != policy).toArray(ObligationPolicy[]::new);
        if (kept.length == 0) {
            attached.remove(template);
        } else {
            attached.put(template, kept);
        }
    }

    /**
     * The policies attached here that react to {@code template}, in attach order. The array is
     * never changed (attaching makes a new one), so delivery may iterate it while policies change.
     */
    ObligationPolicy[] policiesFor(EventTemplate template) {
        if (attached == null) {
            return NO_POLICIES;
        }
        ObligationPolicy[] list = attached.get(template);
        return list == null ? NO_POLICIES : list;
    }

    /** Lets {@code observer} see every event delivered here, after this node's policies; once. */
    public void addObserver(EventObserver observer) {
        if (observers == null) {
            observers = new ArrayList<>(1);
        }
        if (!observers.contains(observer)) {
            observers.add(observer);
        }
    }

    public void removeObserver(EventObserver observer) {
        if (observers != null) {
            observers.remove(observer);
        }
    }

    void notifyObservers(Execution ex, EventTemplate template, Object[] values) {
        if (observers != null) {
            for (EventObserver o : List.copyOf(observers)) {
                o.observe(ex, template, values);
            }
        }
    }

    private static final ObligationPolicy[] NO_POLICIES = new ObligationPolicy[0];

    @Override
    public String toString() {
        String path = path();
        return path == null ? "<" + type.name() + ">" : "<" + type.name() + " " + path + ">";
    }
}
