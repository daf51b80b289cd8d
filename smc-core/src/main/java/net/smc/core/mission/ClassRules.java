package net.smc.core.mission;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import net.smc.core.mission.ClassSpec.BoundDecl;
import net.smc.core.mission.ClassSpec.ExclusiveDecl;
import net.smc.core.mission.ClassSpec.ParallelDecl;
import net.smc.core.mission.ClassSpec.Ref;
import net.smc.core.mission.ClassSpec.RoleDecl;
import net.smc.core.mission.ClassSpec.SecondaryDecl;
import net.smc.core.xml.XmlElement;

/**
 * The rules a mission class's names must follow together: managed roles exist, management forms a
 * tree rooted at the commander, colocation rules and bounds name known roles and agree with each
 * other. Each broken rule is reported at the element that breaks it; checking goes on.
 */
final class ClassRules {
    private final ClassSpec spec;
    private final Reporter reporter;
    /** Each managed role's manager, as far as the file gives one consistently. */
    private final Map<String, String> managerOf = new LinkedHashMap<>();

    private ClassRules(ClassSpec spec, Reporter reporter) {
        this.spec = spec;
        this.reporter = reporter;
    }

    static void check(ClassSpec spec, Reporter reporter) {
        ClassRules rules = new ClassRules(spec, reporter);
        rules.management();
        rules.colocation();
        rules.bounds();
    }

    private boolean known(String role) {
        return spec.role(role) != null;
    }

    private void management() {
        RoleDecl commander = spec.role(Mission.COMMANDER);
        if (commander == null) {
            reporter.error(spec.root(), "no <commanderBehaviour>; the management tree is rooted at the commander role");
        } else if (commander.hasCardinality()) {
            reporter.error(commander.cardinality(), "the commander has a <cardinality>; a team has exactly one commander");
        }
        for (RoleDecl role : spec.roles()) {
            Set<String> listed = new HashSet<>();
            for (Ref managed : role.manages()) {
                String problem = !known(managed.name())
                        ? "unknown role '" + managed.name() + "'; a managed role needs its own <" + managed.name() + "Behaviour>"
                        : managed.name().equals(role.name()) ? "role '" + role.name() + "' manages itself; "
                                + "the management relation is a tree rooted at the commander"
                        : managed.name().equals(Mission.COMMANDER) ? "the commander is managed by '" + role.name()
                                + "'; the commander is the root of the management tree and has no manager"
                        : !listed.add(managed.name()) ? "role '" + managed.name() + "' is listed twice in "
                                + "<roleManagement>; each managed role is listed once"
                        : managerOf.containsKey(managed.name()) ? "role '" + managed.name() + "' is already managed by '"
                                + managerOf.get(managed.name()) + "'; the management relation is a tree: each role has one manager"
                        : null;
                if (problem != null) {
                    reporter.error(managed.at(), problem);
                } else {
                    managerOf.put(managed.name(), role.name());
                }
            }
        }
        if (commander != null) {
            reachability();
        }
    }

    /** Roles without a manager, and roles whose managers go round in a cycle. */
    private void reachability() {
        for (RoleDecl role : spec.roles()) {
            if (role.name().equals(Mission.COMMANDER)) {
                continue;
            }
            if (!managerOf.containsKey(role.name())) {
                reporter.error(role.at(), "role '" + role.name() + "' has no manager; every role but the commander is "
                        + "managed by one role (list it in a <manages> of its manager)");
                continue;
            }
            List<String> chain = new ArrayList<>(List.of(role.name()));
            String up = managerOf.get(role.name());
            while (up != null && !up.equals(Mission.COMMANDER) && !chain.contains(up)) {
                chain.add(up);
                up = managerOf.get(up);
            }
            if (up != null && up.equals(role.name())) {
                chain.add(up);
                reporter.error(role.at(), "role '" + role.name() + "' is in a management cycle ("
                        + String.join(" -> ", chain) + "); the management relation is a tree rooted at the commander");
            }
        }
    }

    private void colocation() {
        Map<String, XmlElement> parallelPairs = new HashMap<>();
        for (ParallelDecl rule : spec.parallel()) {
            knownRole(rule.role(), "role");
            if (rule.with().isEmpty()) {
                reporter.error(rule.at(), "empty attribute 'with'; <parallel> names the roles its role runs beside");
            }
            for (Ref with : rule.with()) {
                if (knownRole(with, "with") && with.name().equals(rule.role().name())) {
                    reporter.error(rule.at(), "role '" + with.name() + "' is parallel with itself; "
                            + "a colocation rule pairs different roles");
                }
                parallelPairs.put(pair(rule.role().name(), with.name()), rule.at());
            }
        }
        for (ExclusiveDecl rule : spec.exclusive()) {
            Set<String> names = new HashSet<>();
            for (Ref role : rule.roles()) {
                if (knownRole(role, "roles") && !names.add(role.name())) {
                    reporter.error(rule.at(), "role '" + role.name() + "' is listed twice; a colocation rule pairs different roles");
                }
            }
            if (rule.roles().size() < 2) {
                reporter.error(rule.at(), "names " + rule.roles().size() + " role" + (rule.roles().size() == 1 ? "" : "s")
                        + "; <exclusive> names two roles or more that switch on one vehicle");
            }
            for (int i = 0; i < rule.roles().size(); i++) {
                for (int j = i + 1; j < rule.roles().size(); j++) {
                    String a = rule.roles().get(i).name();
                    String b = rule.roles().get(j).name();
                    if (!a.equals(b) && parallelPairs.containsKey(pair(a, b))) {
                        reporter.error(rule.at(), "roles '" + a + "' and '" + b + "' are both parallel (line "
                                + parallelPairs.get(pair(a, b)).line() + ") and exclusive; two roles on one vehicle "
                                + "either run together or switch, not both");
                    }
                }
            }
        }
        secondaries(parallelPairs);
    }

    private void secondaries(Map<String, XmlElement> parallelPairs) {
        Map<String, String> primaryOf = new HashMap<>();
        for (SecondaryDecl rule : spec.secondary()) {
            boolean bothKnown = knownRole(rule.role(), "role") & knownRole(rule.primary(), "primary");
            if (bothKnown && !primaryOf.containsKey(rule.role().name())) {
                primaryOf.put(rule.role().name(), rule.primary().name());
            } else if (bothKnown) {
                reporter.error(rule.at(), "role '" + rule.role().name() + "' is already secondary to '"
                        + primaryOf.get(rule.role().name()) + "'; a secondary role has one primary");
                rule = null;
            }
            if (rule != null && bothKnown) {
                secondary(rule, parallelPairs);
            }
        }
        for (SecondaryDecl rule : spec.secondary()) {
            String primary = rule.primary().name();
            if (primaryOf.containsKey(primary) && primaryOf.containsKey(rule.role().name())) {
                reporter.error(rule.at(), "primary '" + primary + "' is itself secondary to '" + primaryOf.get(primary)
                        + "'; a primary role is not secondary");
            }
        }
    }

    private void secondary(SecondaryDecl rule, Map<String, XmlElement> parallelPairs) {
        String role = rule.role().name();
        String primary = rule.primary().name();
        if (role.equals(primary)) {
            reporter.error(rule.at(), "role '" + role + "' is secondary to itself; a secondary role rides on another role");
        } else if (spec.role(primary).manages().stream().noneMatch(m -> m.name().equals(role))) {
            reporter.error(rule.at(), "'" + primary + "' does not manage '" + role
                    + "'; a primary role manages its secondary roles");
        } else if (!parallelPairs.containsKey(pair(role, primary)) && !exclusivePair(role, primary)) {
            reporter.error(rule.at(), "no <parallel> or <exclusive> rule lets '" + role + "' share a vehicle with '"
                    + primary + "'; a secondary role must be allowed beside its primary");
        }
    }

    private boolean exclusivePair(String a, String b) {
        return spec.exclusive().stream().anyMatch(e -> e.roles().stream().anyMatch(r -> r.name().equals(a))
                && e.roles().stream().anyMatch(r -> r.name().equals(b)));
    }

    private void bounds() {
        Map<String, BoundDecl> seen = new HashMap<>();
        for (BoundDecl bound : spec.bounds()) {
            if (!knownRole(bound.role(), "role")) {
                continue;
            }
            if (seen.putIfAbsent(bound.role().name(), bound) != null) {
                reporter.error(bound.at(), "role '" + bound.role().name() + "' is bounded twice; a role has one <bound>");
            } else if (bound.min() != null && bound.max() != null && bound.min() > bound.max()) {
                reporter.error(bound.at(), "min " + bound.min() + " is more than max " + bound.max()
                        + "; a bound's min must be at most its max");
            }
        }
    }

    /** Reports a colocation rule or bound naming an unknown role; answers whether it is known. */
    private boolean knownRole(Ref ref, String attribute) {
        if (known(ref.name())) {
            return true;
        }
        reporter.error(ref.at(), "unknown role '" + ref.name() + "' in '" + attribute
                + "'; colocation rules and bounds name roles of the mission class");
        return false;
    }

    private static String pair(String a, String b) {
        return a.compareTo(b) <= 0 ? a + " " + b : b + " " + a;
    }
}
