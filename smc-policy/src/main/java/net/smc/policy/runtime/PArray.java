package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

/** A PonderTalk array: growable, 0-based, holding any values. */
@Managed("Array")
public final class PArray implements net.smc.policy.api.ArrayValue {
    private final ArrayList<Object> items;

    public PArray() {
        this.items = new ArrayList<>();
    }

    public PArray(Collection<?> values) {
        this.items = new ArrayList<>(values);
    }

    public static PArray of(Object... values) {
        return new PArray(List.of(values));
    }

    public int size() {
        return items.size();
    }

    public Object get(int i) {
        return items.get(i);
    }

    /** A read-only view of the elements. */
    public List<Object> items() {
        return java.util.Collections.unmodifiableList(items);
    }

    public void add(Object v) {
        items.add(v);
    }

    private int index(BigDecimal i) {
        Integer n = Numbers.intValue(i);
        if (n == null || n < 0 || n >= items.size()) {
            throw new PonderError("index " + i + " out of range for array of size " + items.size());
        }
        return n;
    }

    @Op("at:")
    public Object at(BigDecimal i) {
        return items.get(index(i));
    }

    @Op("at:put:")
    public Object atPut(BigDecimal i, Object v) {
        items.set(index(i), v);
        return v;
    }

    @Op("add:")
    public PArray addOp(Object v) {
        items.add(v);
        return this;
    }

    @Op("addAll:")
    public PArray addAll(CallContext ctx, PArray other) {
        ctx.execution().charge(other.items.size(), "Array addAll:");
        items.addAll(new ArrayList<>(other.items));
        return this;
    }

    @Op("size")
    public BigDecimal sizeOp() {
        return BigDecimal.valueOf(items.size());
    }

    @Op("has:")
    public boolean has(BigDecimal i) {
        Integer n = Numbers.intValue(i);
        return n != null && n >= 0 && n < items.size();
    }

    @Op("hasObject:")
    public boolean hasObject(Object v) {
        for (Object item : items) {
            if (Values.same(item, v)) {
                return true;
            }
        }
        return false;
    }

    @Op("remove:")
    public Object remove(BigDecimal i) {
        return items.remove(index(i));
    }

    @Op("removeObject:")
    public PArray removeObject(Object v) {
        for (int i = 0; i < items.size(); i++) {
            if (Values.same(items.get(i), v)) {
                items.remove(i);
                break;
            }
        }
        return this;
    }

    @Op("removeAll")
    public PArray removeAll() {
        items.clear();
        return this;
    }

    @Op("do:")
    public PArray each(CallContext ctx, Block body) {
        for (Object item : new ArrayList<>(items)) {
            ctx.call(body, item);
        }
        return this;
    }

    @Op("collect:")
    public PArray collect(CallContext ctx, Block body) {
        PArray out = new PArray();
        for (Object item : new ArrayList<>(items)) {
            out.items.add(ctx.call(body, item));
        }
        return out;
    }

    @Op("asHash")
    public PHash asHash(CallContext ctx) {
        if (items.size() % 2 != 0) {
            throw new PonderError("asHash needs an even number of elements, got " + items.size());
        }
        ctx.execution().charge(items.size(), "Array asHash");
        PHash h = new PHash();
        for (int i = 0; i < items.size(); i += 2) {
            h.put(Values.print(items.get(i)), items.get(i + 1));
        }
        return h;
    }

    @Override
    public String toString() {
        return Values.print(this);
    }
}
