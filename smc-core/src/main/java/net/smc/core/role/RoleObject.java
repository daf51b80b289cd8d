package net.smc.core.role;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import net.smc.policy.runtime.AuthorisationPolicy;
import net.smc.policy.runtime.CellRuntime;
import net.smc.policy.runtime.Domain;
import net.smc.policy.api.Managed;
import net.smc.policy.runtime.ObligationPolicy;
import net.smc.policy.api.Op;
import net.smc.policy.api.PonderError;

/**
 * A loaded role as PonderTalk sees it: the domain {@code root/role/<name>}, holding
 * {@code policy} (the role-mission's obligation policies), {@code auth} (its authorisation
 * policies), {@code task} (its tasks) and {@code peers} (subjects standing for collaborating roles'
 * cells, see {@link ExternalGateway}). A domain, so that paths run through it, and a managed object
 * with the management operations common to all roles ({@link ExternalInterface#MANAGEMENT_OPERATIONS})
 * plus {@code reassign:scheme:}, which the paper's Table II sends to {@code root/role/commander}.
 */
@Managed("Role")
final class RoleObject extends Domain {
    static final String POLICY = "policy";
    static final String AUTH = "auth";
    static final String TASK = "task";
    static final String PEERS = "peers";

    private final Reassignment reassignment;
    private Role role;

    RoleObject(CellRuntime runtime, Role role, Reassignment reassignment) {
        super(runtime);
        this.role = role;
        this.reassignment = reassignment;
        for (String part : List.of(POLICY, AUTH, TASK, PEERS)) {
            put(part, new Domain(runtime));
        }
    }

    Role role() {
        return role;
    }

    void describe(Role newer) {
        this.role = newer;
    }

    /**
     * One of the role's own domains.
     *
     * @throws PonderError when a script removed or replaced it
     */
    Domain part(String name) {
        if (get(name) instanceof Domain d) {
            return d;
        }
        throw new PonderError("root/role/" + role.name() + "/" + name + " is missing or not a domain; role '"
                + role.name() + "' keeps its " + name + " there");
    }

    @Op("name")
    public String name() {
        return role.name();
    }

    @Op("manages")
    public List<String> manages() {
        return List.copyOf(role.manages());
    }

    @Op("policies")
    public List<String> policies() {
        return List.copyOf(part(POLICY).entries().keySet());
    }

    @Op("authorisations")
    public List<String> authorisations() {
        return List.copyOf(part(AUTH).entries().keySet());
    }

    @Op("tasks")
    public List<String> tasks() {
        return List.copyOf(part(TASK).entries().keySet());
    }

    /** Whether the role's obligation or authorisation policy of this name is active. */
    @Op("isEnabled:")
    public boolean isEnabled(String policy) {
        Object p = policyNamed(policy);
        return p instanceof ObligationPolicy o ? o.isActive() : ((AuthorisationPolicy) p).active();
    }

    /** Enables one of the role's policies: how a role-mission controls its own policies (section II-B.3). */
    @Op("enable:")
    public boolean enable(String policy) {
        return setActive(policy, true);
    }

    @Op("disable:")
    public boolean disable(String policy) {
        return setActive(policy, false);
    }

    /**
     * Asks the team protocols to re-assign a role this role manages.
     *
     * @throws PonderError when this role does not manage {@code managed}
     */
    @Op("reassign:scheme:")
    public void reassign(String managed, String scheme) {
        if (!role.manages().contains(managed)) {
            throw new PonderError("role '" + role.name() + "' does not manage role '" + managed
                    + "', so it cannot re-assign it (it manages " + role.manages() + ")");
        }
        reassignment.reassign(role.name(), managed, scheme);
    }

    private boolean setActive(String policy, boolean on) {
        Object p = policyNamed(policy);
        if (p instanceof ObligationPolicy o) {
            return o.active(on);
        }
        return ((AuthorisationPolicy) p).active(on);
    }

    private Object policyNamed(String policy) {
        for (String part : List.of(POLICY, AUTH)) {
            Object p = part(part).get(policy);
            if (p instanceof ObligationPolicy || p instanceof AuthorisationPolicy) {
                return p;
            }
        }
        throw new PonderError("role '" + role.name() + "' has no policy '" + policy + "' (it has " + allPolicyNames() + ")");
    }

    private List<String> allPolicyNames() {
        List<String> names = new ArrayList<>();
        for (String part : List.of(POLICY, AUTH)) {
            for (Map.Entry<String, Object> e : part(part).entries().entrySet()) {
                names.add(e.getKey());
            }
        }
        return names;
    }
}
