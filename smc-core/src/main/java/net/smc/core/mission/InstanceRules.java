package net.smc.core.mission;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import net.smc.core.mission.ClassSpec.BoundDecl;
import net.smc.core.mission.ClassSpec.ParamDecl;
import net.smc.core.mission.ClassSpec.Ref;
import net.smc.core.mission.ClassSpec.RoleDecl;
import net.smc.core.mission.InstanceSpec.Cardinality;
import net.smc.core.mission.InstanceSpec.ParamValue;
import net.smc.core.mission.InstanceSpec.RoleEntry;

/**
 * Checks a mission instance against its class (parameters, roles, cardinalities) and every policy
 * URI against the repository. Without a readable class only the policies are checked.
 */
final class InstanceRules {
    private final InstanceSpec instance;
    private final ClassSpec spec;
    private final Reporter reporter;

    private InstanceRules(InstanceSpec instance, ClassSpec spec, Reporter reporter) {
        this.instance = instance;
        this.spec = spec;
        this.reporter = reporter;
    }

    /**
     * @param spec the class, or {@code null} when it could not be read (its problem is reported already)
     */
    static void check(InstanceSpec instance, ClassSpec spec, PolicyCheck policies, Reporter reporter) {
        InstanceRules rules = new InstanceRules(instance, spec, reporter);
        if (spec != null) {
            rules.className();
            rules.parameters();
            rules.teamParameters();
            rules.roles();
        }
        for (RoleEntry role : instance.roles()) {
            List<Ref> uris = new java.util.ArrayList<>(role.policies());
            uris.addAll(role.authorisations());
            for (Ref policy : uris) {
                policies.problem(policy.name()).ifPresent(problem -> reporter.textError(policy.at(), problem));
            }
        }
    }

    private String classLabel() {
        return spec.name() == null ? "the mission class" : "class '" + spec.name() + "'";
    }

    private void className() {
        if (instance.className() != null && spec.name() != null && !instance.className().equals(spec.name())) {
            reporter.textError(instance.classAt(), "names class '" + instance.className() + "' but "
                    + instance.classHref() + " defines '" + spec.name() + "'; <missionClass> names the class its href points to");
        }
    }

    private void parameters() {
        for (ParamValue value : instance.parameters()) {
            ParamDecl decl = spec.parameter(value.name());
            if (decl == null) {
                List<String> names = spec.parameters().stream().map(ParamDecl::name).toList();
                reporter.error(value.at(), "unknown parameter '" + value.name() + "'; " + classLabel() + " declares "
                        + (names.isEmpty() ? "no parameters" : String.join(", ", names)));
            } else if (decl.type() != null) {
                try {
                    decl.type().parse(value.text());
                } catch (IllegalArgumentException e) {
                    reporter.textError(value.at(), e.getMessage() + "; parameter '" + value.name() + "' is declared "
                            + decl.type().xmlName() + " in " + classLabel());
                }
            }
        }
        for (ParamDecl decl : spec.parameters()) {
            if (instance.parameters().stream().noneMatch(v -> v.name().equals(decl.name()))) {
                reporter.error(instance.parametersAt(), "no value for parameter '" + decl.name() + "'"
                        + (decl.type() == null ? "" : " (" + decl.type().xmlName() + ")")
                        + "; an instance gives every parameter of its class a value");
            }
        }
    }

    /**
     * The parameters the team protocols read keep their rules ({@link TeamParameters}): a mission
     * that breaks one would load here and be refused by every cell. A value that does not parse as
     * its declared type is reported already and left out; a team parameter the class declares with a
     * type the protocols cannot read (a time as a string, say) is reported at its declaration.
     */
    private void teamParameters() {
        Map<String, Object> values = new HashMap<>();
        Map<String, ParamValue> at = new HashMap<>();
        for (ParamValue value : instance.parameters()) {
            ParamDecl decl = spec.parameter(value.name());
            if (decl == null || decl.type() == null) {
                continue;
            }
            List<String> wanted = TeamParameters.typesOf(value.name());
            if (!wanted.isEmpty() && !wanted.contains(decl.type().xmlName())) {
                reporter.textError(value.at(), "parameter '" + value.name() + "' is declared " + decl.type().xmlName()
                        + " in " + classLabel() + "; the team protocols read it as " + String.join(" or ", wanted));
                continue;
            }
            try {
                values.put(value.name(), decl.type().parse(value.text()));
                at.put(value.name(), value);
            } catch (IllegalArgumentException e) {
                // reported by parameters()
            }
        }
        if (values.get("scheme") instanceof String scheme) {
            try {
                TeamParameters.scheme(scheme);
            } catch (IllegalArgumentException e) {
                reporter.textError(at.get("scheme").at(), e.getMessage() + "; the team protocols read parameter 'scheme'");
            }
        }
        if (!values.containsKey("comTimeout") || !values.containsKey("failureTimeout")) {
            return;
        }
        long com = TeamParameters.millis("comTimeout", values.get("comTimeout"));
        long failure = TeamParameters.millis("failureTimeout", values.get("failureTimeout"));
        long backups = values.containsKey("backups") ? TeamParameters.count("backups", values.get("backups")) : 1;
        TeamParameters.timing(com, failure, backups).ifPresent(problem -> {
            ParamValue where = at.get(problem.parameter());
            reporter.textError(where == null ? at.get("failureTimeout").at() : where.at(),
                    problem.message() + "; the team protocols read parameter '" + problem.parameter() + "'");
        });
    }

    private void roles() {
        for (RoleEntry entry : instance.roles()) {
            RoleDecl decl = spec.role(entry.name());
            if (decl == null) {
                List<String> names = spec.roles().stream().map(RoleDecl::name).toList();
                reporter.error(entry.at(), "unknown role '" + entry.name() + "'; " + classLabel() + " defines "
                        + (names.isEmpty() ? "no roles" : "roles " + String.join(", ", names)));
                continue;
            }
            cardinality(entry, decl);
            if (entry.policies().isEmpty()) {
                reporter.error(entry.at(), "role '" + entry.name() + "' has no <policy>; a role's behaviour "
                        + "comes from at least one role-mission policy");
            }
        }
        for (RoleDecl decl : spec.roles()) {
            if (instance.role(decl.name()) == null) {
                reporter.error(instance.root(), "no <" + decl.name() + "> for role '" + decl.name() + "'; an instance "
                        + "gives every role of its class its policies" + (decl.hasCardinality() ? " and cardinality" : ""));
            }
        }
    }

    private void cardinality(RoleEntry entry, RoleDecl decl) {
        Cardinality cardinality = entry.cardinality();
        // The class is told when it gives the commander a cardinality; the instance is not told again.
        boolean declared = decl.hasCardinality() && !decl.name().equals(Mission.COMMANDER);
        if (declared && cardinality == null) {
            reporter.error(entry.at(), "no <cardinality> for role '" + entry.name() + "'; " + classLabel()
                    + " declares <cardinality>int</cardinality> for it, so the instance gives <minimal> and <optimal>");
        } else if (!declared && cardinality != null) {
            reporter.error(cardinality.at(), "role '" + entry.name() + "' has no <cardinality> in " + classLabel()
                    + "; such a role has exactly one holder and the instance gives none");
        } else if (cardinality != null) {
            for (BoundDecl bound : spec.bounds()) {
                if (bound.role().name().equals(entry.name())) {
                    bounded(entry.name(), cardinality, bound);
                }
            }
        }
    }

    private void bounded(String role, Cardinality cardinality, BoundDecl bound) {
        if (bound.min() != null && bound.max() != null && bound.min() > bound.max()) {
            return;   // the class is told; a bound that cannot hold says nothing about the instance
        }
        if (bound.min() != null && cardinality.minimal() != null && cardinality.minimal() < bound.min()) {
            reporter.textError(cardinality.minimalAt(), "minimal " + cardinality.minimal() + " for role '" + role
                    + "' is below the class's bound min=" + bound.min() + " (line " + bound.at().line()
                    + "); an instance's cardinalities stay within the class's bounds");
        }
        if (bound.max() != null && cardinality.optimal() != null && cardinality.optimal() > bound.max()) {
            reporter.textError(cardinality.optimalAt(), "optimal " + cardinality.optimal() + " for role '" + role
                    + "' is above the class's bound max=" + bound.max() + " (line " + bound.at().line()
                    + "); an instance's cardinalities stay within the class's bounds");
        }
    }
}
