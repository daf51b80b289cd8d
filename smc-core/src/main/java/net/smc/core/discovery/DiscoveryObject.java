package net.smc.core.discovery;

import java.util.LinkedHashSet;
import java.util.Objects;
import java.util.Set;
import net.smc.core.capability.CapabilitySummary;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Handle;
import net.smc.policy.api.Op;
import net.smc.policy.api.ArrayValue;
import net.smc.policy.api.PonderError;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code root/discovery}: the operations the paper's role-assignment policy (Table I) uses when a
 * discovery reply arrives as a {@code newUAV} event, and {@code hold}/{@code resume}, with which a
 * role-mission decides when its manager recruits at all. It decides nothing itself; policies
 * decide whom to ask and when, and {@link DiscoveryActions} does the asking. Counts what it does.
 *
 * <pre>{@code
 * DiscoveryObject discovery = new DiscoveryObject(CredentialCheck.sharedToken("team-7"), protocols::requestFullCapability);
 * discovery.install(cell);   // root/discovery
 * }</pre>
 */
@Managed("Discovery")
public final class DiscoveryObject {
    /** Where it sits under root. */
    public static final String NAME = "discovery";

    private static final Logger LOG = LoggerFactory.getLogger(DiscoveryObject.class);
    private static final String CHECK = "uav:has:cap:auth:";

    private final CredentialCheck credentials;
    private final DiscoveryActions actions;
    private long accepted;
    private long lacking;
    private long rejectedCredentials;
    private long requests;

    public DiscoveryObject(CredentialCheck credentials, DiscoveryActions actions) {
        this.credentials = Objects.requireNonNull(credentials, "credentials");
        this.actions = Objects.requireNonNull(actions, "actions");
    }

    /** Puts this object at {@code root/discovery}; answers its handle. */
    public Handle install(PolicyEngine cell) {
        Handle handle = PolicyEngine.manage(this);
        cell.root().put(NAME, handle);
        return handle;
    }

    /**
     * Whether a newly discovered vehicle has every resource in {@code resources} by its capability
     * summary, and presented an acceptable credential.
     *
     * @param capability a {@link CapabilitySummary} (as the discovery event carries it) or an array of
     *                   resource names
     * @throws PonderError when {@code capability} is neither
     */
    @Op(CHECK)
    public boolean check(String uav, ArrayValue resources, Object capability, Object credential) {
        Set<String> has = resourcesOf(capability);
        Set<String> missing = new LinkedHashSet<>();
        for (Object wanted : resources.items()) {
            if (!has.contains(PolicyEngine.print(wanted))) {
                missing.add(PolicyEngine.print(wanted));
            }
        }
        if (!missing.isEmpty()) {
            lacking++;
            LOG.debug("vehicle {} lacks {}", uav, missing);
            return false;
        }
        Object presented = credential instanceof Handle m ? m.impl() : credential;
        if (!credentials.accepts(uav, presented)) {
            rejectedCredentials++;
            LOG.debug("vehicle {} presented an unacceptable credential", uav);
            return false;
        }
        accepted++;
        return true;
    }

    /** Asks {@code uav} for its full capability description, for {@code role}. */
    @Op("fullCapReq:role:")
    public void requestFullCapability(String uav, String role) {
        requests++;
        actions.requestFullCapability(uav, role);
    }

    /**
     * Holds this cell's recruiting: as a manager it discovers no one, and so assigns no role, until
     * {@link #resume}. A role-mission that assembles its team on an event holds it when loaded.
     */
    @Op("hold")
    public void hold() {
        actions.holdRecruiting(true);
    }

    /** Resumes the recruiting {@link #hold} held: the manager discovers at its next tick. */
    @Op("resume")
    public void resume() {
        actions.holdRecruiting(false);
    }

    /** Whether recruiting is held now. */
    @Op("isHeld")
    public boolean isHeld() {
        return actions.recruitingHeld();
    }

    /** Checks passed. */
    public long accepted() {
        return accepted;
    }

    /** Checks failed because the vehicle lacked a resource. */
    public long lacking() {
        return lacking;
    }

    /** Checks failed because of the credential. */
    public long rejectedCredentials() {
        return rejectedCredentials;
    }

    /** Full capability requests made. */
    public long requests() {
        return requests;
    }

    private static Set<String> resourcesOf(Object capability) {
        Object value = capability instanceof Handle m ? m.impl() : capability;
        if (value instanceof CapabilitySummary summary) {
            return summary.resources();
        }
        if (value instanceof ArrayValue names) {
            Set<String> out = new LinkedHashSet<>();
            names.items().forEach(n -> out.add(PolicyEngine.print(n)));
            return out;
        }
        throw new PonderError("argument 3 of '" + CHECK + "' on Discovery must be a CapabilitySummary or an array of"
                + " resource names, got " + PolicyEngine.className(capability));
    }
}
