package net.smc.core.role;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import net.smc.policy.api.PolicyHandle;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Managed;
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
final class RoleObject {
    static final String POLICY = "policy";
    static final String AUTH = "auth";
    static final String TASK = "task";
    static final String PEERS = "peers";

    private final Reassignment reassignment;
    private final DomainHandle domain;
    private Role role;

    RoleObject(PolicyEngine cell, Role role, Reassignment reassignment) {
        this.role = role;
        this.reassignment = reassignment;
        this.domain = cell.newDomain(this);
        for (String part : List.of(POLICY, AUTH, TASK, PEERS)) {
            domain.put(part, cell.newDomain());
        }
    }

    /** The domain {@code root/role/<name>}, which answers this object's operations. */
    DomainHandle domain() {
        return domain;
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
    DomainHandle part(String name) {
        if (domain.get(name) instanceof DomainHandle d) {
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
        return policyNamed(policy).active();
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
        return policyNamed(policy).active(on);
    }

    private PolicyHandle policyNamed(String policy) {
        for (String part : List.of(POLICY, AUTH)) {
            Object p = part(part).get(policy);
            if (p instanceof PolicyHandle found) {
                return found;
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
