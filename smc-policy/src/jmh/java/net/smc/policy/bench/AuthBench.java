package net.smc.policy.bench;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import net.smc.policy.api.AuthMode;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.runtime.AuthorisationPolicy;
import net.smc.policy.runtime.Domain;
import net.smc.policy.runtime.EventTemplate;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Goal: with authorisation on (default deny) and 1,000 authorisation policies over a domain tree
 * five levels below root, an event whose obligation policy (stored in a level-5 subject domain)
 * does {@code target at: "k" put: level} on a level-5 target domain costs at most 1 µs more than
 * with authorisation off. Variants: {@code OFF} (baseline), {@code DENY} (one positive policy on
 * (subject domain, target domain, "at:put:") allows the put), {@code DENY_TOGGLE} (as DENY, and
 * an unrelated policy is enabled or disabled every 1,000 events, which drops the decision cache).
 * Setup and teardown check, untimed, that the put is allowed, that a put nobody allowed is denied,
 * and that disabling the allowing policy denies the put (the cache follows policy changes).
 */
@State(Scope.Thread)
@Fork(2)
@Warmup(iterations = 2, time = 1)
@Measurement(iterations = 5, time = 1)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class AuthBench {
    private static final int BRANCHES = 3;
    private static final int DEPTH = 5;
    private static final int POLICIES = 1000;
    private static final String SUBJECT = "root/a0/b1/c2/d0/e1";
    private static final String TARGET = "root/a1/b2/c0/d1/e2";
    private static final String OTHER_TARGET = "root/a1/b2/c0/d1/e0";

    @Param({"OFF", "DENY", "DENY_TOGGLE"})
    String variant;

    /** DENY_TOGGLE: events per policy change ({@code -p toggleEvery=1} prices one cache rebuild). */
    @Param({"1000"})
    int toggleEvery;

    private final List<Diagnostic> errors = Bench.errors();
    private PolicyEngine cell;
    private EventTemplate alarm;
    private Domain target;
    private AuthorisationPolicy allow;
    private AuthorisationPolicy unrelated;
    private int count;

    @Setup(Level.Trial)
    public void setUp() {
        cell = Bench.cell(variant.equals("OFF") ? AuthMode.OFF : AuthMode.DENY, errors);
        List<String> domains = new ArrayList<>();
        StringBuilder boot = new StringBuilder("d := root/factory/domain.\n");
        tree("root", 0, domains, boot);
        Bench.run(cell, "tree", boot.toString(), errors);
        Bench.run(cell, "authpolicies", authPolicies(domains), errors);
        Bench.run(cell, "boot", """
                root/event at: "alarm" put: (root/factory/event create: #("name" "level")).
                root/event at: "probe" put: (root/factory/event create: #("name" "level")).
                target := %s.
                other := %s.
                p := root/factory/ecapolicy create.
                p event: root/event/alarm; condition: [:level | level > 5]; action: [:level | target at: "k" put: level].
                p active: true.
                %s at: "alarm" put: p.
                q := root/factory/ecapolicy create.
                q event: root/event/probe; action: [:level | other at: "k" put: level].
                q active: true.
                %s at: "probe" put: q.
                """.formatted(TARGET, OTHER_TARGET, SUBJECT, SUBJECT), errors);
        cell.endBoot();
        alarm = (EventTemplate) cell.template("root/event/alarm");
        target = (Domain) cell.resolve(TARGET);
        allow = (AuthorisationPolicy) cell.resolve("root/policy/allow");
        unrelated = (AuthorisationPolicy) cell.resolve("root/policy/unrelated");
        checkDecisions();
    }

    /** Domains {@code a0..a2} under root, {@code b0..b2} under each, ... down to {@code e0..e2}. */
    private static void tree(String parent, int level, List<String> domains, StringBuilder text) {
        if (level == DEPTH) {
            return;
        }
        for (int i = 0; i < BRANCHES; i++) {
            String path = parent + "/" + (char) ('a' + level) + i;
            text.append(parent).append(" at: \"").append((char) ('a' + level)).append(i).append("\" put: d create.\n");
            domains.add(path);
            tree(path, level + 1, domains, text);
        }
    }

    /**
     * 1,000 policies: ten about the measured (subject path, target path) pairs (only the innermost,
     * positive one decides the put; the others are overridden, or for other actions), the rest on
     * random pairs not on both measured paths, with random actions, focus, negatives and finals.
     */
    private static String authPolicies(List<String> domains) {
        List<String> subjectPath = ancestors(SUBJECT);
        List<String> targetPath = ancestors(TARGET);
        StringBuilder text = new StringBuilder("f := root/factory/authpolicy.\n");
        text.append(policy("allow", SUBJECT, "at:put:", TARGET, "st", ""));
        text.append(policy("n1", "root", "at:put:", "root", "st", " reqneg;"));
        text.append(policy("n2", subjectPath.get(1), "*", targetPath.get(1), "st", " reqneg;"));
        text.append(policy("n3", subjectPath.get(3), "at:put:", targetPath.get(2), "t", " reqneg; repneg;"));
        text.append(policy("n4", subjectPath.get(4), "at:put:", TARGET, "s", " reqneg;"));
        text.append(policy("n5", SUBJECT, "at:put:", targetPath.get(4), "st", " reqneg;"));
        text.append(policy("f1", "root", "remove:", "root", "st", " reqneg; final;"));
        text.append(policy("f2", subjectPath.get(2), "removeAll", targetPath.get(3), "t", " reqneg; final;"));
        text.append(policy("o1", SUBJECT, "at:", TARGET, "st", " reqneg;"));
        text.append(policy("o2", SUBJECT, "size", TARGET, "st", ""));
        String[] actions = {"at:put:", "at:", "*", "size", "remove:", "listNames"};
        String[] focus = {"s", "t", "st"};
        Random random = new Random(42);
        List<String> nodes = new ArrayList<>(domains);
        nodes.add("root");
        for (int i = 10; i < POLICIES; i++) {
            String s;
            String t;
            do {
                s = nodes.get(random.nextInt(nodes.size()));
                t = nodes.get(random.nextInt(nodes.size()));
            } while (subjectPath.contains(s) && targetPath.contains(t));
            String modifiers = (random.nextInt(3) == 0 ? " reqneg;" : "") + (random.nextInt(20) == 0 ? " final;" : "");
            text.append(policy(i == 10 ? "unrelated" : "r" + i, s, actions[random.nextInt(actions.length)], t,
                    focus[random.nextInt(focus.length)], modifiers));
        }
        return text.toString();
    }

    private static String policy(String name, String subject, String action, String target, String focus,
                                 String modifiers) {
        return "a := f subject: " + subject + " action: \"" + action + "\" target: " + target + " focus: \"" + focus
                + "\". a" + modifiers + " active: true. root/policy at: \"" + name + "\" put: a.\n";
    }

    /** root, root/a0, root/a0/b1, ... the path itself. */
    private static List<String> ancestors(String path) {
        List<String> out = new ArrayList<>();
        String[] parts = path.split("/");
        String at = parts[0];
        out.add(at);
        for (int i = 1; i < parts.length; i++) {
            at = at + "/" + parts[i];
            out.add(at);
        }
        return out;
    }

    @Benchmark
    public boolean raise() {
        if (variant.equals("DENY_TOGGLE") && ++count >= toggleEvery) {
            count = 0;
            unrelated.active(!unrelated.active());
        }
        return cell.raise(alarm, "boiler", BigDecimal.valueOf(7));
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        Bench.check(errors.isEmpty(), "errors while measuring: " + errors);
        Bench.check(BigDecimal.valueOf(7).equals(target.get("k")), "target after measuring: " + target.entries());
        checkDecisions();
    }

    /** Untimed: allowed put, denied put, and the cache following a change of the allowing policy. */
    private void checkDecisions() {
        boolean on = !variant.equals("OFF");
        target.put("k", BigDecimal.ZERO);
        cell.raise(alarm, "boiler", BigDecimal.valueOf(7));
        Bench.check(errors.isEmpty() && BigDecimal.valueOf(7).equals(target.get("k")), "allowed put: " + errors);

        cell.raise("root/event/probe", "boiler", BigDecimal.valueOf(8));
        Domain other = (Domain) cell.resolve(OTHER_TARGET);
        Bench.check(on ? other.get("k") == null && errors.size() == 1
                && errors.get(0).message().contains("Ponder2AuthorizationException: at:put:")
                : BigDecimal.valueOf(8).equals(other.get("k")) && errors.isEmpty(), "unallowed put: " + errors);
        errors.clear();

        allow.active(false);
        cell.raise(alarm, "boiler", BigDecimal.valueOf(6));
        Bench.check(on ? BigDecimal.valueOf(7).equals(target.get("k")) && errors.size() == 1
                : BigDecimal.valueOf(6).equals(target.get("k")) && errors.isEmpty(), "put after disabling: " + errors);
        errors.clear();
        allow.active(true);
        cell.raise(alarm, "boiler", BigDecimal.valueOf(7));
        Bench.check(errors.isEmpty() && BigDecimal.valueOf(7).equals(target.get("k")), "put after re-enabling: " + errors);
    }
}
