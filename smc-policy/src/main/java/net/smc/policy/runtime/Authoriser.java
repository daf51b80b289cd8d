package net.smc.policy.runtime;

import net.smc.policy.api.Nil;
import net.smc.policy.api.PonderError;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import net.smc.policy.api.AuthMode;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.lang.SourcePos;

/**
 * Decides whether a send from a subject to a target is authorised, at the four enforcement
 * points, by Ponder2's domain-nesting precedence (smc-policy/PONDERTALK.md section 9). For each (subject,
 * target, selector) it builds once, and caches, the ordered list of candidate policies of every
 * path combination; a send then only evaluates conditions in order. The cache is dropped whenever
 * a policy or a domain membership changes.
 */
final class Authoriser {
    private static final int REQUEST_SUBJECT = 0;
    private static final int REQUEST_TARGET = 1;
    private static final int REPLY_TARGET = 2;
    private static final int REPLY_SUBJECT = 3;
    /** Paths followed from root to one object; beyond this (or {@link #MAX_PATH_LENGTH}) the send is denied. */
    private static final int MAX_PATHS = 64;
    private static final int MAX_PATH_LENGTH = 256;
    private static final int MAX_CACHED_PLANS = 100_000;
    /** Variables every condition sees besides its parameters. */
    private static final String[] PARTIES = {"p_subject", "p_target"};

    private final CellRuntime runtime;
    private final AuthMode mode;
    private final HashMap<Key, Plan> plans = new HashMap<>();
    /** Active policies by subject, each list in activation order. */
    private final Map<ManagedObject, List<AuthorisationPolicy>> activeBySubject = new HashMap<>();

    private record Key(Object subject, ManagedObject target, String selector) {
    }

    /** The candidates of one path combination at one enforcement point, in decision order. */
    private record Combination(AuthorisationPolicy[] finals, AuthorisationPolicy[] normals) {
    }

    /** Candidates per enforcement point. */
    private record Plan(Combination[][] points) {
    }

    /** A target in no domain: never checked. */
    private static final Plan UNCHECKED = new Plan(null);
    /** More paths than can be followed: denied, since a path not followed might deny. */
    private static final Plan TOO_MANY_PATHS = new Plan(null);

    /** The paths from root down to one object, and whether some were left out. */
    private static final class Paths {
        final List<List<ManagedObject>> list = new ArrayList<>();
        boolean overflow;
    }

    Authoriser(CellRuntime runtime, AuthMode mode) {
        this.runtime = runtime;
        this.mode = mode;
    }

    /** A policy was activated or deactivated. */
    void activeChanged(AuthorisationPolicy policy) {
        if (policy.active) {
            activeBySubject.computeIfAbsent(policy.subject, s -> new ArrayList<>()).add(policy);
        } else {
            List<AuthorisationPolicy> ofSubject = activeBySubject.get(policy.subject);
            if (ofSubject != null) {
                ofSubject.remove(policy);
                if (ofSubject.isEmpty()) {
                    activeBySubject.remove(policy.subject);
                }
            }
        }
        plans.clear();
    }

    /** A policy's modifiers or conditions changed. */
    void policiesChanged() {
        plans.clear();
    }

    void invalidate() {
        plans.clear();
    }

    /** Invokes {@code op} if the request is allowed, then checks the reply. */
    Object invoke(Interpreter interpreter, Execution ex, Operation op, ManagedObject receiver, Object target,
                  Object[] args, SourcePos pos) {
        Object subject = ex.source;
        Plan plan = plan(subject, receiver, op.selector);
        if (plan == UNCHECKED) {
            return interpreter.invokeUnchecked(ex, op, receiver, target, args, pos);
        }
        if (plan == TOO_MANY_PATHS) {
            throw new PonderError("Ponder2AuthorizationException: " + op.selector + " (the subject or target lies on more than "
                    + MAX_PATHS + " domain paths, or on one deeper than " + MAX_PATH_LENGTH + "; denied)");
        }
        check(ex, plan, REQUEST_SUBJECT, subject, receiver, op.selector, args);
        check(ex, plan, REQUEST_TARGET, subject, receiver, op.selector, args);
        Object result = interpreter.invokeUnchecked(ex, op, receiver, target, args, pos);
        Object[] reply = {result};
        check(ex, plan, REPLY_TARGET, subject, receiver, op.selector, reply);
        check(ex, plan, REPLY_SUBJECT, subject, receiver, op.selector, reply);
        return result;
    }

    private void check(Execution ex, Plan plan, int point, Object subject, ManagedObject target, String selector,
                       Object[] values) {
        if (!decide(ex, plan.points[point], point, subject, target, values, defaultDecision())) {
            throw new PonderError("Ponder2AuthorizationException: " + selector);
        }
    }

    /**
     * Whether {@code subject} may take {@code action} on {@code target}, checked at both request
     * points, for an action that is not an operation (an event forwarded from another cell, a
     * remote evaluation). With {@code explicit}, the target's side needs an authorisation policy
     * that allows it: the cell's default decision does not.
     */
    boolean permits(Execution ex, Object subject, ManagedObject target, String action, Object[] args, boolean explicit) {
        Plan plan = plan(subject, target, action);
        if (plan == UNCHECKED) {
            return !explicit;
        }
        if (plan == TOO_MANY_PATHS) {
            return false;
        }
        return decide(ex, plan.points[REQUEST_SUBJECT], REQUEST_SUBJECT, subject, target, args, defaultDecision())
                && decide(ex, plan.points[REQUEST_TARGET], REQUEST_TARGET, subject, target, args,
                        !explicit && defaultDecision());
    }

    private boolean decide(Execution ex, Combination[] combinations, int point, Object subject, ManagedObject target,
                           Object[] values, boolean defaultAllows) {
        boolean anyAllow = false;
        for (Combination c : combinations) {
            Boolean decision = first(ex, c.finals, point, subject, target, values);
            if (decision == null) {
                decision = first(ex, c.normals, point, subject, target, values);
            }
            if (decision == Boolean.FALSE) {
                return false;
            }
            if (decision == Boolean.TRUE) {
                anyAllow = true;
            }
        }
        return anyAllow || defaultAllows;
    }

    private boolean defaultDecision() {
        return runtime.booting() || mode == AuthMode.ALLOW;
    }

    private Boolean first(Execution ex, AuthorisationPolicy[] candidates, int point, Object subject,
                          ManagedObject target, Object[] values) {
        boolean request = point == REQUEST_SUBJECT || point == REQUEST_TARGET;
        for (AuthorisationPolicy p : candidates) {
            if (holds(ex, request ? p.requestConditions : p.replyConditions, subject, target, values)) {
                return (request ? p.requestNegative : p.replyNegative) ? Boolean.FALSE : Boolean.TRUE;
            }
        }
        return null;
    }

    /** Runs conditions with root as the source, so that they are not themselves checked. */
    private boolean holds(Execution ex, List<Block> conditions, Object subject, ManagedObject target, Object[] values) {
        if (conditions.isEmpty()) {
            return true;
        }
        Object previous = ex.source;
        ex.source = runtime.root();
        try {
            for (Block condition : conditions) {
                Object answer;
                try {
                    answer = runtime.interpreter().call(ex, condition, bind(condition, subject, target, values),
                            PARTIES, new Object[] {subject, target});
                } catch (UnitAbort abort) {
                    throw abort;
                } catch (PonderError e) {
                    e.at(condition.pos());
                    runtime.report(ex, new Diagnostic(e.pos(), "AuthorisationPolicy: condition error: " + e.getMessage()));
                    return false;
                }
                if (answer != Boolean.TRUE) {
                    return false;
                }
            }
            return true;
        } finally {
            ex.source = previous;
        }
    }

    private static Object[] bind(Block condition, Object subject, ManagedObject target, Object[] values) {
        String[] params = condition.code.params;
        Object[] args = new Object[params.length];
        int next = 0;
        for (int i = 0; i < params.length; i++) {
            if (params[i].equals("p_subject")) {
                args[i] = subject;
            } else if (params[i].equals("p_target")) {
                args[i] = target;
            } else {
                args[i] = next < values.length ? values[next++] : Nil.NIL;
            }
        }
        return args;
    }

    private Plan plan(Object subject, ManagedObject target, String selector) {
        Key key = new Key(subject, target, selector);
        Plan plan = plans.get(key);
        if (plan == null) {
            if (plans.size() >= MAX_CACHED_PLANS) {
                plans.clear();
            }
            plan = build(subject, target, selector);
            plans.put(key, plan);
        }
        return plan;
    }

    private Plan build(Object subject, ManagedObject target, String selector) {
        // Root is in no domain, so, like any target in no domain, it is never checked.
        Paths targets = target == runtime.root() ? new Paths() : paths(target);
        if (targets.overflow) {
            return TOO_MANY_PATHS;
        }
        if (targets.list.isEmpty()) {
            return UNCHECKED;
        }
        List<List<ManagedObject>> targetPaths = targets.list;
        List<List<ManagedObject>> subjectPaths = List.of();
        if (subject instanceof ManagedObject s) {
            Paths subjects = paths(s);
            if (subjects.overflow) {
                return TOO_MANY_PATHS;
            }
            subjectPaths = subjects.list.isEmpty() ? List.of(List.of(s)) : subjects.list;
        }
        Map<ManagedObject, List<AuthorisationPolicy>> bySubject = activeBySubject;
        Combination[][] points = new Combination[4][];
        for (int point = 0; point < 4; point++) {
            boolean subjectSide = point == REQUEST_SUBJECT || point == REPLY_SUBJECT;
            boolean request = point == REQUEST_SUBJECT || point == REQUEST_TARGET;
            List<Combination> combinations = new ArrayList<>();
            for (List<ManagedObject> sp : subjectPaths) {
                for (List<ManagedObject> tp : targetPaths) {
                    Combination c = combination(bySubject, sp, tp, selector, subjectSide, request);
                    if (c != null) {
                        combinations.add(c);
                    }
                }
            }
            points[point] = combinations.toArray(new Combination[0]);
        }
        return new Plan(points);
    }

    private static Combination combination(Map<ManagedObject, List<AuthorisationPolicy>> bySubject,
                                           List<ManagedObject> subjectPath, List<ManagedObject> targetPath,
                                           String selector, boolean subjectSide, boolean request) {
        List<AuthorisationPolicy> finals = new ArrayList<>();
        List<List<AuthorisationPolicy>> normalsByPair = new ArrayList<>();
        for (ManagedObject s : subjectPath) {
            List<AuthorisationPolicy> ofSubject = bySubject.getOrDefault(s, List.of());
            for (ManagedObject t : targetPath) {
                List<AuthorisationPolicy> negatives = new ArrayList<>();
                List<AuthorisationPolicy> positives = new ArrayList<>();
                List<AuthorisationPolicy> normalNegatives = new ArrayList<>();
                List<AuthorisationPolicy> normalPositives = new ArrayList<>();
                for (AuthorisationPolicy p : ofSubject) {
                    if (p.target != t || !p.matches(selector) || !(subjectSide ? p.atSubject : p.atTarget)) {
                        continue;
                    }
                    boolean negative = request ? p.requestNegative : p.replyNegative;
                    if (p.isFinal) {
                        (negative ? negatives : positives).add(p);
                    } else {
                        (negative ? normalNegatives : normalPositives).add(p);
                    }
                }
                finals.addAll(negatives);
                finals.addAll(positives);
                normalNegatives.addAll(normalPositives);
                normalsByPair.add(normalNegatives);
            }
        }
        List<AuthorisationPolicy> normals = new ArrayList<>();
        for (int i = normalsByPair.size() - 1; i >= 0; i--) {
            normals.addAll(normalsByPair.get(i));
        }
        if (finals.isEmpty() && normals.isEmpty()) {
            return null;
        }
        return new Combination(finals.toArray(new AuthorisationPolicy[0]), normals.toArray(new AuthorisationPolicy[0]));
    }

    /** Every path from root down to {@code object}; none if it is in no domain tree. */
    private Paths paths(ManagedObject object) {
        Paths out = new Paths();
        collect(object, new ArrayList<>(), out);
        return out;
    }

    private void collect(ManagedObject at, List<ManagedObject> below, Paths out) {
        if (below.contains(at)) {
            return;
        }
        if (out.list.size() >= MAX_PATHS || below.size() >= MAX_PATH_LENGTH) {
            out.overflow = true;
            return;
        }
        below.add(at);
        if (at == runtime.root()) {
            List<ManagedObject> path = new ArrayList<>(below);
            java.util.Collections.reverse(path);
            out.list.add(path);
        } else {
            for (Domain parent : at.parents()) {
                collect(parent, below, out);
            }
        }
        below.remove(below.size() - 1);
    }
}
