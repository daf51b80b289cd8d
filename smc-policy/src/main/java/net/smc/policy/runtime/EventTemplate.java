package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import java.util.List;

/**
 * An event template: a kind of event with named attributes. Obligation policies react to events
 * of exactly one template; raising an event delivers it synchronously.
 */
@Managed("EventTemplate")
public final class EventTemplate extends ManagedObject implements net.smc.policy.api.EventHandle {
    private final CellRuntime runtime;
    private final String[] names;

    public EventTemplate(CellRuntime runtime, List<String> names) {
        this.runtime = runtime;
        this.names = names.stream().map(String::intern).toArray(String[]::new);
    }

    @Op("create")
    static EventTemplate create(CallContext ctx) {
        return new EventTemplate(ctx.runtime(), List.of());
    }

    @Op("create:")
    static EventTemplate create(CallContext ctx, PArray names) {
        return new EventTemplate(ctx.runtime(), names.items().stream().map(Values::print).toList());
    }

    /** The attribute names, in order. */
    public List<String> attributeNames() {
        return List.of(names);
    }

    int indexOf(String name) {
        for (int i = 0; i < names.length; i++) {
            if (names[i] == name || names[i].equals(name)) {
                return i;
            }
        }
        return -1;
    }

    /** Raises an event with values in name order; extra values are ignored. */
    @Op("create:")
    public EventTemplate raise(CallContext ctx, PArray values) {
        raise(ctx.execution(), values.items().toArray());
        return this;
    }

    /** Raises an event of a template without attributes. */
    @Op("create")
    public EventTemplate raise(CallContext ctx) {
        raise(ctx.execution(), new Object[0]);
        return this;
    }

    /** Raises an event with values taken from a hash by attribute name. */
    @Op("fromHash:")
    public EventTemplate fromHash(CallContext ctx, PHash values) {
        Object[] ordered = new Object[names.length];
        for (int i = 0; i < names.length; i++) {
            ordered[i] = values.at(names[i]);
        }
        raise(ctx.execution(), ordered);
        return this;
    }

    /** Raises an event within a run (values in name order). */
    public void raise(Execution ex, Object[] values) {
        if (values.length < names.length) {
            throw new PonderError("too few arguments for event, got " + values.length + " wanted " + names.length);
        }
        Object[] exact = values.length == names.length ? values : java.util.Arrays.copyOf(values, names.length);
        runtime.deliver(ex, this, exact);
    }
}
