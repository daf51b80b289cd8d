package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import java.util.ArrayList;
import java.util.List;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.lang.SourcePos;

/**
 * An obligation (event-condition-action) policy. Created inactive; reacts to events of one
 * template at the nodes it is attached to; conditions are ANDed in order, then every action runs.
 * Block parameters bind by name to the event's attributes. Errors are reported, or given to the
 * {@code onError:} handler, and never reach the script that raised the event.
 */
@Managed("ObligationPolicy")
public final class ObligationPolicy extends ManagedObject implements net.smc.policy.api.PolicyHandle {
    private final CellRuntime runtime;
    private EventTemplate template;
    private final List<Block> conditions = new ArrayList<>();
    private final List<Block> actions = new ArrayList<>();
    private final List<Boolean> wholeEvent = new ArrayList<>();
    private final List<ManagedObject> attachedTo = new ArrayList<>();
    private Block errorHandler;
    private boolean active;
    private long attachOrder;

    public ObligationPolicy(CellRuntime runtime) {
        this.runtime = runtime;
        runtime.created(this);
    }

    /** The nodes the policy is attached to, in the order it was attached. */
    public List<ManagedObject> attachments() {
        return List.copyOf(attachedTo);
    }

    @Op("create")
    static ObligationPolicy create(CallContext ctx) {
        return new ObligationPolicy(ctx.runtime());
    }

    EventTemplate template() {
        return template;
    }

    long attachOrder() {
        return attachOrder;
    }

    @Override
    public boolean isObligation() {
        return true;
    }

    @Override
    public void retire() {
        active(false);
        for (ManagedObject node : attachments()) {
            detach(node);
        }
    }

    public boolean isActive() {
        return active;
    }

    @Op("event:")
    public EventTemplate event(EventTemplate newTemplate) {
        if (template != null) {
            for (ManagedObject node : attachedTo) {
                node.detach(this, template);
            }
        }
        template = newTemplate;
        for (ManagedObject node : attachedTo) {
            node.attach(this);
        }
        runtime.policiesChanged();
        return newTemplate;
    }

    @Op("condition:")
    public ObligationPolicy condition(Block condition) {
        conditions.add(condition);
        runtime.policiesChanged();
        return this;
    }

    @Op("action:")
    public ObligationPolicy action(Block action) {
        actions.add(action);
        wholeEvent.add(false);
        runtime.policiesChanged();
        return this;
    }

    /** An action that receives the whole event as one hash. */
    @Op("eaction:")
    public ObligationPolicy eaction(Block action) {
        actions.add(action);
        wholeEvent.add(true);
        runtime.policiesChanged();
        return this;
    }

    @Op("active:")
    public boolean active(boolean on) {
        if (on != active) {
            runtime.policiesChanged();
        }
        active = on;
        if (on && attachOrder == 0) {
            attach(runtime.root());   // the first activation of a policy never attached; one detached since stays so
        }
        return on;
    }

    @Op("active")
    public boolean active() {
        return active;
    }

    @Op("attach:")
    public ObligationPolicy attach(ManagedObject node) {
        if (!attachedTo.contains(node)) {
            if (attachOrder == 0) {
                attachOrder = runtime.nextAttachOrder();
            }
            attachedTo.add(node);
            if (template != null) {
                node.attach(this);
            }
            runtime.policiesChanged();
        }
        return this;
    }

    /** Detaches the policy from a node (an extension of Ponder2's selectors). */
    @Op("detach:")
    public ObligationPolicy detach(ManagedObject node) {
        if (attachedTo.remove(node)) {
            if (template != null) {
                node.detach(this, template);
            }
            runtime.policiesChanged();
        }
        return this;
    }

    @Op("onError:")
    public ObligationPolicy onError(Block handler) {
        errorHandler = handler;
        return this;
    }

    /** Runs the policy for one event, with itself as the source of its statements. */
    void fire(Execution ex, Event event) {
        if (!active) {
            return;
        }
        ex.checkCallDepth();   // not contained here: the send that raised the event is where the loop shows
        Object previous = ex.source;
        ex.source = this;
        ex.firing++;
        try {
            for (Block condition : conditions) {
                Object answer;
                try {
                    answer = runtime.interpreter().call(ex, condition, bind(condition, event));
                } catch (UnitAbort abort) {
                    throw abort;
                } catch (CallDepthExceeded runaway) {
                    if (ex.firing > 1) {
                        throw runaway;
                    }
                    failed(ex, "condition", runaway.at(condition.pos()));
                    return;
                } catch (PonderError e) {
                    failed(ex, "condition", e.at(condition.pos()));
                    return;
                }
                if (answer != Boolean.TRUE) {
                    if (answer != Boolean.FALSE) {
                        failed(ex, "condition", new PonderError("condition answered "
                                + Values.describe(answer) + ", not a boolean", condition.pos()));
                    }
                    return;
                }
            }
            for (int i = 0; i < actions.size(); i++) {
                Block action = actions.get(i);
                try {
                    Object[] args = wholeEvent.get(i) ? new Object[] {event.asHash()} : bind(action, event);
                    runtime.interpreter().call(ex, action, args);
                } catch (UnitAbort abort) {
                    throw abort;
                } catch (CallDepthExceeded runaway) {
                    if (ex.firing > 1) {
                        throw runaway; // an enclosing policy's firing reports it, once
                    }
                    failed(ex, "action", runaway.at(action.pos()));
                    return;
                } catch (PonderError e) {
                    failed(ex, "action", e.at(action.pos()));
                }
            }
        } finally {
            ex.firing--;
            ex.source = previous;
        }
    }

    private static Object[] bind(Block block, Event event) {
        String[] params = block.code.params;
        Object[] args = new Object[params.length];
        for (int i = 0; i < params.length; i++) {
            Object v = event.get(params[i]);
            if (v == null) {
                throw new PonderError("hash key '" + params[i] + "' not found");
            }
            args[i] = v;
        }
        return args;
    }

    /**
     * Reports an error of a condition or an action, unless the {@code onError:} handler takes it. A
     * handler that fails itself is reported with the error it was handling, which is not lost.
     */
    private void failed(Execution ex, String where, PonderError error) {
        if (errorHandler != null) {
            try {
                runtime.interpreter().call(ex, errorHandler, new ErrorValue(error));
                return;
            } catch (UnitAbort abort) {
                throw abort;
            } catch (PonderError handlerError) {
                PonderError handled = error;
                error = handlerError.at(errorHandler.pos());
                SourcePos was = handled.pos();
                runtime.report(ex, new Diagnostic(error.pos(), "ObligationPolicy: unhandled onError error: " + error.getMessage()
                        + " (while handling the " + where + " error: " + handled.getMessage()
                        + (was == null ? "" : " at " + was.source() + ":" + was.line() + ":" + was.column()) + ")"));
                return;
            }
        }
        SourcePos pos = error.pos();
        runtime.report(ex, new Diagnostic(pos, "ObligationPolicy: unhandled " + where + " error: " + error.getMessage()));
    }
}
