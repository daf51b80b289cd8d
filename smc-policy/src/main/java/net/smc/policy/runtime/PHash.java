package net.smc.policy.runtime;

import net.smc.policy.api.Nil;
import net.smc.policy.api.PonderError;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;

/** A PonderTalk hash: string keys, any values, insertion order. */
@Managed("Hash")
public final class PHash implements net.smc.policy.api.HashValue {
    private final LinkedHashMap<String, Object> map = new LinkedHashMap<>();

    public PHash() {
    }

    public PHash(Map<String, ?> entries) {
        map.putAll(entries);
    }

    public Object get(String key) {
        return map.get(key);
    }

    public void put(String key, Object value) {
        map.put(key, value);
    }

    public int size() {
        return map.size();
    }

    public boolean containsKey(String key) {
        return map.containsKey(key);
    }

    /** A read-only view of the entries by key, in insertion order. */
    Map<String, Object> asMap() {
        return java.util.Collections.unmodifiableMap(map);
    }

    /** A read-only view of the entries, in insertion order. */
    public Set<Map.Entry<String, Object>> entries() {
        return java.util.Collections.unmodifiableMap(map).entrySet();
    }

    @Op("at:")
    public Object at(String key) {
        Object v = map.get(key);
        if (v == null) {
            throw new PonderError("hash key '" + Numbers.abbreviate(key) + "' not found");
        }
        return v;
    }

    @Op("at:ifAbsent:")
    public Object atIfAbsent(CallContext ctx, String key, Object otherwise) {
        Object v = map.get(key);
        if (v != null) {
            return v;
        }
        return otherwise instanceof Block b ? ctx.call(b) : otherwise;
    }

    @Op("at:put:")
    public Object atPut(String key, Object value) {
        map.put(key, value);
        return value;
    }

    @Op("has:")
    public boolean has(String key) {
        return map.containsKey(key);
    }

    @Op("hasObject:")
    public boolean hasObject(Object v) {
        for (Object value : map.values()) {
            if (Values.same(value, v)) {
                return true;
            }
        }
        return false;
    }

    @Op("remove:")
    public Object remove(String key) {
        Object v = map.remove(key);
        return v == null ? Nil.NIL : v;
    }

    @Op("removeObject:")
    public PHash removeObject(Object v) {
        map.values().removeIf(value -> Values.same(value, v));
        return this;
    }

    @Op("removeAll")
    public PHash removeAll() {
        map.clear();
        return this;
    }

    @Op("size")
    public BigDecimal sizeOp() {
        return BigDecimal.valueOf(map.size());
    }

    @Op("listNames")
    public PArray listNames(CallContext ctx) {
        ctx.execution().charge(map.size(), "Hash listNames");
        return new PArray(map.keySet());
    }

    @Op("listObjects")
    public PArray listObjects(CallContext ctx) {
        ctx.execution().charge(map.size(), "Hash listObjects");
        return new PArray(map.values());
    }

    @Op("asArray")
    public PArray asArray(CallContext ctx) {
        ctx.execution().charge(2L * map.size(), "Hash asArray");
        PArray out = new PArray();
        map.forEach((k, v) -> {
            out.add(k);
            out.add(v);
        });
        return out;
    }

    @Op("do:")
    public PHash each(CallContext ctx, Block body) {
        for (Map.Entry<String, Object> e : new ArrayList<>(map.entrySet())) {
            ctx.call(body, e.getKey(), e.getValue());
        }
        return this;
    }

    @Op("collect:")
    public PArray collect(CallContext ctx, Block body) {
        PArray out = new PArray();
        for (Map.Entry<String, Object> e : new ArrayList<>(map.entrySet())) {
            out.add(ctx.call(body, e.getKey(), e.getValue()));
        }
        return out;
    }

    @Override
    public String toString() {
        return Values.print(this);
    }
}
