package net.smc.core.role;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import net.smc.core.role.ExternalCallException.Kind;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.EventHandle;
import net.smc.policy.api.Handle;
import net.smc.policy.api.PonderError;

/**
 * Where invocations from other vehicles enter a role's external interface (the paper's section
 * II-B.2.A): management operations on the role object, exported task operations, and required
 * events. Each is sent with the caller's subject, {@code root/role/<role>/peers/<caller role>/<cell>},
 * through {@link PolicyEngine#sendAs}, so the receiving role's authorisation policies decide it (with the
 * cell's default decision, deny in a deployed cell, when none applies). The messaging layer turns
 * incoming requests into calls of this class.
 *
 * <pre>{@code
 * ExternalGateway gateway = new ExternalGateway(roleManager);
 * Object answer = gateway.invoke(new Caller("c7", "commander"), "surveyor", "goTo:y:", 3, 4);
 * gateway.raise(new Caller("c9", "hdetector"), "aggregator", "hazardDetected", "hazardDetected", "c9", "gas", 1, 2);
 * }</pre>
 */
public final class ExternalGateway {
    private static final String DENIAL = "Ponder2AuthorizationException";

    private final RoleManager roles;

    public ExternalGateway(RoleManager roles) {
        this.roles = Objects.requireNonNull(roles, "roles");
    }

    /**
     * Invokes an operation of a role's external interface on behalf of {@code caller}.
     *
     * @return the operation's answer, as a PonderTalk value
     * @throws ExternalCallException when the role is absent, the operation is not in its external
     *                               interface, authorisation denies it, or it fails
     */
    public Object invoke(Caller caller, String role, String selector, Object... args) {
        RoleObject object = loaded(role);
        Object receiver;
        String what;
        if (ExternalInterface.MANAGEMENT_OPERATIONS.contains(selector)) {
            receiver = object.domain();
            what = "management operation '" + selector + "' of role '" + role + "'";
        } else {
            TaskOperation exported = object.role().external().exportedOperation(selector);
            if (exported == null) {
                throw new ExternalCallException(Kind.NOT_IN_INTERFACE, "operation '" + selector
                        + "' is not in the external interface of role '" + role + "' (it exports "
                        + object.role().external().exported().stream().map(TaskOperation::selector).toList() + ")");
            }
            receiver = object.part(RoleObject.TASK).get(exported.task());
            what = "operation '" + selector + "' of task '" + exported.task() + "' of role '" + role + "'";
        }
        return send(caller, object, receiver, selector, args, what);
    }

    /**
     * Raises, on behalf of {@code caller}, an event the role requires ({@code root/event/<event>});
     * it is checked as the selector {@code create:} on the event template, and delivered from the
     * caller's subject up to root.
     *
     * @param values the event's attribute values, in the template's order
     * @throws ExternalCallException as {@link #invoke}
     */
    public void raise(Caller caller, String role, String event, Object... values) {
        RoleObject object = loaded(role);
        if (!object.role().external().requiredEvents().contains(event)) {
            throw new ExternalCallException(Kind.NOT_IN_INTERFACE, "event '" + event
                    + "' is not required by role '" + role + "', so other roles may not raise it there (it requires "
                    + object.role().external().requiredEvents() + ")");
        }
        Object template = roles.cell().root().get("event") instanceof DomainHandle events ? events.get(event) : null;
        if (!(template instanceof EventHandle)) {
            throw new ExternalCallException(Kind.FAILED, "event '" + event + "' required by role '" + role
                    + "' has no template at root/event/" + event);
        }
        send(caller, object, template, "create:", new Object[] {java.util.Arrays.asList(values)}, "event '" + event + "' of role '" + role + "'");
    }

    /**
     * Raises (or sends as {@code selector}) at the object at {@code path} an event another cell's
     * {@code EventForwarder} forwarded, with the caller's subject in the receiving role: the role
     * the path lies in ({@code role/<role>/...}), else the cell's first role. This cell's
     * authorisation policies decide (the action {@code forwardTo:} on the target, or the selector).
     *
     * @throws ExternalCallException when this cell holds no role, it is denied, or it fails
     */
    public void receiveEvent(Caller caller, String path, String selector, String event, Map<String, Object> attributes) {
        RoleObject object = receiving(path);
        String what = "event '" + event + "' forwarded to root/" + path;
        try {
            roles.cell().arrivals().receiveEvent(peer(object, caller), path, selector, event, attributes);
        } catch (PonderError e) {
            throw refused(caller, object, what, e);
        }
    }

    /**
     * Evaluates PonderTalk text another cell sent, with the caller's subject in the cell's first
     * role, if an authorisation policy allows the action {@code evaluate:} on that role's domain.
     *
     * @return the value of its last statement ({@code printed}: its printed form)
     * @throws ExternalCallException when this cell holds no role, it is denied, or it fails
     */
    public Object evaluate(Caller caller, String text, boolean printed) {
        RoleObject object = receiving("");
        try {
            return roles.cell().arrivals().evaluate(peer(object, caller), object.domain(), "remote:" + caller.cell(), text, printed);
        } catch (PonderError e) {
            throw refused(caller, object, "evaluation of PonderTalk text", e);
        }
    }

    private RoleObject receiving(String path) {
        String[] parts = path.split("/");
        if (parts.length >= 2 && parts[0].equals("role") && roles.roleObject(parts[1]) != null) {
            return roles.roleObject(parts[1]);
        }
        for (String name : roles.loadedRoles()) {
            return loaded(name);
        }
        throw new ExternalCallException(Kind.NO_SUCH_ROLE, "this cell holds no role, so no peer of it may act here");
    }

    private static ExternalCallException refused(Caller caller, RoleObject object, String what, PonderError e) {
        if (e.getMessage() != null && e.getMessage().startsWith(DENIAL)) {
            return new ExternalCallException(Kind.DENIED, "role '" + caller.role() + "' on cell '" + caller.cell()
                    + "' may not cause " + what + ": denied by the authorisation policies of role '"
                    + object.role().name() + "' (" + e.getMessage() + ")");
        }
        return new ExternalCallException(Kind.FAILED, what + ", from role '" + caller.role() + "' on cell '"
                + caller.cell() + "', failed: " + e.getMessage());
    }

    private RoleObject loaded(String role) {
        RoleObject object = roles.roleObject(role);
        if (object == null) {
            throw new ExternalCallException(Kind.NO_SUCH_ROLE, "role '" + role + "' is not loaded on this cell");
        }
        return object;
    }

    private Object send(Caller caller, RoleObject object, Object receiver, String selector, Object[] args, String what) {
        if (receiver == null) {
            throw new ExternalCallException(Kind.FAILED, what + " has no receiver: its task is missing from root/role/"
                    + object.role().name() + "/task");
        }
        Handle subject = peer(object, caller);
        try {
            return roles.cell().sendAs(subject, receiver, selector, args);
        } catch (PonderError e) {
            if (e.getMessage() != null && e.getMessage().startsWith(DENIAL)) {
                throw new ExternalCallException(Kind.DENIED, "role '" + caller.role() + "' on cell '" + caller.cell()
                        + "' may not use " + what + ": denied by the authorisation policies of role '"
                        + object.role().name() + "' (" + e.getMessage() + ")");
            }
            throw new ExternalCallException(Kind.FAILED, what + ", invoked by role '" + caller.role() + "' on cell '"
                    + caller.cell() + "', failed: " + e.getMessage());
        }
    }

    /** The caller's subject, made on its first call; it lives as long as the role. */
    private Handle peer(RoleObject object, Caller caller) {
        DomainHandle peers = object.part(RoleObject.PEERS);
        Object ofRole = peers.get(caller.role());
        if (ofRole == null) {
            ofRole = roles.cell().newDomain();
            peers.put(caller.role(), ofRole);
        }
        if (!(ofRole instanceof DomainHandle callers)) {
            throw new ExternalCallException(Kind.FAILED, "root/role/" + object.role().name() + "/peers/" + caller.role()
                    + " is not a domain; it must hold the subjects of role '" + caller.role() + "'");
        }
        if (callers.get(caller.cell()) instanceof Handle existing) {
            return existing;
        }
        Handle subject = PolicyEngine.manage(new Peer(caller));
        callers.put(caller.cell(), subject);
        return subject;
    }
}
