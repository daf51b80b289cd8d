package net.smc.policy.stdlib;

import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.runtime.EventObserver;
import net.smc.policy.runtime.EventTemplate;
import net.smc.policy.runtime.Execution;
import net.smc.policy.api.Managed;
import net.smc.policy.runtime.ManagedObject;
import net.smc.policy.api.Op;
import net.smc.policy.runtime.PHash;
import net.smc.policy.api.PonderError;
import net.smc.policy.runtime.CellRuntime;
import net.smc.policy.runtime.CallContext;

/**
 * Ponder2's event forwarder, within one cell: attached to objects ({@code attachTo:}), it sees every
 * event raised at or below them and, while active, passes each (of the templates given with
 * {@code forward:}, or all) to its targets: {@code forwardTo: d} raises the event again at
 * {@code d} (its policies and every domain above it see it, with the forwarder as source);
 * {@code forwardTo: o as: "event:"} sends {@code o} that one-argument message with the event as a
 * hash of its attributes. Created inactive. An error while forwarding is reported as
 * {@code EventForwarder: unhandled error: ...} and never reaches the raising statement; a
 * forwarding loop ends at the call depth limit.
 */
@Managed("EventForwarder")
final class EventForwarder extends ManagedObject implements EventObserver {
    private final CellRuntime runtime;
    private final Map<Object, String> targets = new LinkedHashMap<>();
    private Set<EventTemplate> templates;
    private boolean active;

    @Op("create")
    EventForwarder(CallContext ctx) {
        this.runtime = ctx.runtime();
    }

    @Op("attachTo:")
    void attachTo(ManagedObject object) {
        object.addObserver(this);
    }

    /** Extension: stops seeing the events of {@code object}. */
    @Op("detachFrom:")
    void detachFrom(ManagedObject object) {
        object.removeObserver(this);
    }

    @Op("forwardTo:")
    void forwardTo(ManagedObject target) {
        targets.put(target, null);
    }

    @Op("forwardTo:as:")
    void forwardTo(Object target, String selector) {
        if (selector.chars().filter(c -> c == ':').count() != 1 || !selector.endsWith(":")) {
            throw new PonderError("forwardTo:as: needs a one-argument keyword selector such as 'event:', got '" + selector + "'");
        }
        targets.put(target, selector);
    }

    @Op("remove:")
    void remove(Object target) {
        targets.remove(target);
    }

    /** Forwards only events of this template (repeatable); without any, every event. */
    @Op("forward:")
    void forward(EventTemplate template) {
        if (templates == null) {
            templates = new LinkedHashSet<>();
        }
        templates.add(template);
    }

    @Op("active:")
    boolean active(boolean on) {
        active = on;
        return on;
    }

    @Op("active")
    boolean active() {
        return active;
    }

    @Override
    public void observe(Execution ex, EventTemplate template, Object[] values) {
        if (!active || (templates != null && !templates.contains(template))) {
            return;
        }
        for (Map.Entry<Object, String> target : List.copyOf(targets.entrySet())) {
            try {
                if (target.getValue() == null) {
                    runtime.deliverAt(ex, (ManagedObject) target.getKey(), template, values);
                } else {
                    PHash event = new PHash();
                    for (int i = 0; i < values.length; i++) {
                        event.put(template.attributeNames().get(i), values[i]);
                    }
                    runtime.sendWithin(ex, this, target.getKey(), target.getValue(), new Object[] {event});
                }
            } catch (PonderError e) {
                runtime.report(new Diagnostic(e.pos(), "EventForwarder: unhandled error: " + e.getMessage()));
            }
        }
    }
}
