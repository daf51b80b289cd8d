package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import java.util.ArrayList;
import java.util.List;

/**
 * An authorisation policy: may {@code subject} send {@code action} to {@code target}? Checked at
 * the subject ({@code focus "s"}), the target ({@code "t"}) or both ({@code "st"}), on the request
 * and on the reply. Positive unless made negative for the request ({@code reqneg}) or the reply
 * ({@code repneg}); {@code final} policies cannot be overridden from inner domains.
 */
@Managed("AuthorisationPolicy")
public final class AuthorisationPolicy extends ManagedObject implements net.smc.policy.api.PolicyHandle {
    private final CellRuntime runtime;
    final ManagedObject subject;
    final String action;
    final ManagedObject target;
    final boolean atSubject;
    final boolean atTarget;
    boolean requestNegative;
    boolean replyNegative;
    boolean isFinal;
    boolean active;
    final List<Block> requestConditions = new ArrayList<>();
    final List<Block> replyConditions = new ArrayList<>();

    AuthorisationPolicy(CellRuntime runtime, ManagedObject subject, String action, ManagedObject target, String focus) {
        this.runtime = runtime;
        this.subject = subject;
        this.action = action;
        this.target = target;
        switch (focus) {
            case "s" -> {
                atSubject = true;
                atTarget = false;
            }
            case "t" -> {
                atSubject = false;
                atTarget = true;
            }
            case "st", "ts" -> {
                atSubject = true;
                atTarget = true;
            }
            default -> throw new PonderError("focus must be \"s\", \"t\" or \"st\", got '" + Numbers.abbreviate(focus) + "'");
        }
        runtime.created(this);
    }

    @Op("subject:action:target:focus:")
    static AuthorisationPolicy create(CallContext ctx, ManagedObject subject, String action, ManagedObject target,
                                      String focus) {
        return new AuthorisationPolicy(ctx.runtime(), subject, action, target, focus);
    }

    private AuthorisationPolicy changed() {
        runtime.policiesChanged();
        if (runtime.authoriser() != null) {
            runtime.authoriser().policiesChanged();
        }
        return this;
    }

    @Op("reqneg")
    public AuthorisationPolicy reqneg() {
        requestNegative = true;
        return changed();
    }

    @Op("repneg")
    public AuthorisationPolicy repneg() {
        replyNegative = true;
        return changed();
    }

    @Op("final")
    public AuthorisationPolicy makeFinal() {
        isFinal = true;
        return changed();
    }

    @Op("reqcondition:")
    public AuthorisationPolicy reqcondition(Block condition) {
        requestConditions.add(condition);
        return changed();
    }

    @Op("repcondition:")
    public AuthorisationPolicy repcondition(Block condition) {
        replyConditions.add(condition);
        return changed();
    }

    @Op("active:")
    public boolean active(boolean on) {
        if (on != active) {
            active = on;
            runtime.policiesChanged();
            if (runtime.authoriser() != null) {
                runtime.authoriser().activeChanged(this);
            }
        }
        return on;
    }

    @Op("active")
    @Override
    public boolean isObligation() {
        return false;
    }

    @Override
    public void retire() {
        active(false);
    }

    public boolean active() {
        return active;
    }

    boolean matches(String selector) {
        return action.equals("*") || action.equals(selector);
    }
}
