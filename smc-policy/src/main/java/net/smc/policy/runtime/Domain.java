package net.smc.policy.runtime;

import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.Nil;
import net.smc.policy.api.PonderError;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A domain: named entries, each any value. Adding a managed object records the domain as one of
 * its parents, which event delivery and authorisation follow.
 */
@Managed("Domain")
public class Domain extends ManagedObject implements DomainHandle {
    private final CellRuntime runtime;
    private final LinkedHashMap<String, Object> entries = new LinkedHashMap<>();

    public Domain(CellRuntime runtime) {
        this.runtime = runtime;
    }

    /** A domain that also answers the operations of {@code type} (see {@link ManagedClass#withOperationsOf}). */
    Domain(CellRuntime runtime, ManagedClass type) {
        super(type);
        this.runtime = runtime;
    }

    @Op("create")
    static Domain create(CallContext ctx) {
        return new Domain(ctx.runtime());
    }

    /** The entry with this name, or {@code null}. */
    public Object get(String name) {
        return entries.get(name);
    }

    /** Adds or replaces an entry; the Java form of {@code at:put:}. */
    public void put(String name, Object value) {
        atPut(name, value);
    }

    /** The entries, in insertion order (read-only). */
    public Map<String, Object> entries() {
        return java.util.Collections.unmodifiableMap(entries);
    }

    String nameOf(ManagedObject child) {
        for (Map.Entry<String, Object> e : entries.entrySet()) {
            if (e.getValue() == child) {
                return e.getKey();
            }
        }
        return null;
    }

    private static void checkName(String name) {
        if (name.isEmpty()) {
            throw new PonderError("invalid name '': letters, digits and _ only");
        }
        for (int i = 0; i < name.length(); i++) {
            char c = name.charAt(i);
            if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) {
                throw new PonderError("invalid name '" + Numbers.abbreviate(name) + "': letters, digits and _ only");
            }
        }
    }

    @Op("at:put:")
    public Object atPut(String name, Object value) {
        checkName(name);
        Object old = entries.put(name, value);
        if (old != value) {
            if (old instanceof ManagedObject m && !entries.containsValue(m)) {
                m.removeParent(this);
            }
            if (value instanceof ManagedObject m) {
                m.addParent(this);
            }
            if (old instanceof ManagedObject || value instanceof ManagedObject) {
                runtime.membershipChanged();
            }
        }
        return value;
    }

    @Op("at:")
    public Object at(String name) {
        Object v = entries.get(name);
        return v == null ? Nil.NIL : v;
    }

    @Op("at:ifAbsent:")
    public Object atIfAbsent(CallContext ctx, String name, Object otherwise) {
        Object v = entries.get(name);
        if (v != null) {
            return v;
        }
        return otherwise instanceof Block b ? ctx.call(b) : otherwise;
    }

    @Op("has:")
    public boolean has(String name) {
        return entries.containsKey(name);
    }

    @Op("hasObject:")
    public boolean hasObject(Object v) {
        for (Object value : entries.values()) {
            if (Values.same(value, v)) {
                return true;
            }
        }
        return false;
    }

    @Op("size")
    public BigDecimal size() {
        return BigDecimal.valueOf(entries.size());
    }

    @Op("listNames")
    public PArray listNames() {
        return new PArray(entries.keySet());
    }

    @Op("listObjects")
    public PArray listObjects() {
        return new PArray(entries.values());
    }

    @Op("asHash")
    public PHash asHash() {
        return new PHash(entries);
    }

    @Op("do:")
    public Domain each(CallContext ctx, Block body) {
        for (Map.Entry<String, Object> e : new ArrayList<>(entries.entrySet())) {
            ctx.call(body, e.getKey(), e.getValue());
        }
        return this;
    }

    @Op("collect:")
    public PArray collect(CallContext ctx, Block body) {
        PArray out = new PArray();
        for (Map.Entry<String, Object> e : new ArrayList<>(entries.entrySet())) {
            out.add(ctx.call(body, e.getKey(), e.getValue()));
        }
        return out;
    }

    /** Follows a relative path such as {@code a/b} from this domain. */
    @Op("resolve:")
    public Object resolve(String path) {
        Object at = this;
        for (String segment : path.split("/", -1)) {
            Object next = at instanceof Domain d ? d.entries.get(segment) : null;
            if (next == null) {
                throw new PonderError("path not found '" + Numbers.abbreviate(path) + "'");
            }
            at = next;
        }
        return at;
    }

    @Op("remove:")
    public Object remove(String name) {
        Object old = entries.remove(name);
        if (old == null) {
            return Nil.NIL;
        }
        forget(old);
        return old;
    }

    private void forget(Object old) {
        if (old instanceof ManagedObject m && !entries.containsValue(m)) {
            m.removeParent(this);
            runtime.membershipChanged();
        }
    }

    @Op("removeObject:")
    public Domain removeObject(Object v) {
        for (String name : new ArrayList<>(entries.keySet())) {
            Object value = entries.get(name);
            if (Values.same(value, v)) {
                entries.remove(name);
                forget(value);
            }
        }
        return this;
    }

    @Op("removeAll")
    public Domain removeAll() {
        for (String name : new ArrayList<>(entries.keySet())) {
            forget(entries.remove(name));
        }
        return this;
    }

    CellRuntime runtime() {
        return runtime;
    }
}
