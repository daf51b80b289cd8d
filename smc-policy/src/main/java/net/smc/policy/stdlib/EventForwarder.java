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
import net.smc.policy.api.TeamAddress;
import net.smc.policy.runtime.Domain;
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
 *
 * <p>A target may also be a domain or object of another cell of the team, written as the string
 * {@code "/team/<cell>/<path>"} ({@link TeamAddress}, in place of Ponder2's RMI URLs): the event
 * goes there over the cell's {@link net.smc.policy.api.TeamLink} by its template's name under
 * {@code root/event} and its attributes, and that cell's authorisation policies decide. The answer
 * comes back as {@code remoteResult}; a refusal is also reported here.
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
    void forwardTo(Object target) {
        targets.put(checkedTarget(target), null);
    }

    @Op("forwardTo:as:")
    void forwardTo(Object target, String selector) {
        if (selector.chars().filter(c -> c == ':').count() != 1 || !selector.endsWith(":")) {
            throw new PonderError("forwardTo:as: needs a one-argument keyword selector such as 'event:', got '" + selector + "'");
        }
        targets.put(TeamAddress.isTeamAddress(target) ? TeamAddress.parse((String) target) : target, selector);
    }

    @Op("remove:")
    void remove(Object target) {
        targets.remove(TeamAddress.isTeamAddress(target) ? TeamAddress.parse((String) target) : target);
    }

    private static Object checkedTarget(Object target) {
        if (target instanceof ManagedObject) {
            return target;
        }
        if (TeamAddress.isTeamAddress(target)) {
            TeamAddress to = TeamAddress.parse((String) target);
            if (to.path().isEmpty()) {
                throw new PonderError("forwardTo: needs a domain of the other cell, as in " + to + "/event; got " + to);
            }
            return to;
        }
        throw new PonderError("forwardTo: needs a domain, or a domain of another cell as \"/team/<cell>/<path>\"; got "
                + net.smc.policy.runtime.Values.print(target));
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
                if (target.getKey() instanceof TeamAddress to) {
                    forwardToCell(to, target.getValue(), template, values);
                } else if (target.getValue() == null) {
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

    private void forwardToCell(TeamAddress to, String selector, EventTemplate template, Object[] values) {
        String name = templateName(template);
        Map<String, Object> attributes = new LinkedHashMap<>();
        for (int i = 0; i < values.length; i++) {
            attributes.put(template.attributeNames().get(i), values[i]);
        }
        runtime.teamLink().forwardEvent(to, selector, name, attributes);
    }

    /** The template's name under root/event, the name other cells know it by. */
    private String templateName(EventTemplate template) {
        if (runtime.root().get("event") instanceof Domain events) {
            for (Map.Entry<String, Object> e : events.entries().entrySet()) {
                if (e.getValue() == template) {
                    return e.getKey();
                }
            }
        }
        throw new PonderError("the event is not stored under root/event, so another cell cannot know it by name");
    }
}
