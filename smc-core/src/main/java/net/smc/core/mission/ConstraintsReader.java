package net.smc.core.mission;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import net.smc.core.mission.ClassSpec.BoundDecl;
import net.smc.core.mission.ClassSpec.ExclusiveDecl;
import net.smc.core.mission.ClassSpec.ParallelDecl;
import net.smc.core.mission.ClassSpec.Ref;
import net.smc.core.mission.ClassSpec.SecondaryDecl;
import net.smc.core.xml.XmlElement;

/**
 * Reads a mission class's {@code <constraints>}: cardinality bounds and colocation rules, each an
 * element whose attributes name roles. Whether those roles exist is {@link ClassRules}'s job.
 */
final class ConstraintsReader {
    private final Reporter reporter;
    final List<ParallelDecl> parallel = new ArrayList<>();
    final List<ExclusiveDecl> exclusive = new ArrayList<>();
    final List<SecondaryDecl> secondary = new ArrayList<>();
    final List<BoundDecl> bounds = new ArrayList<>();

    private ConstraintsReader(Reporter reporter) {
        this.reporter = reporter;
    }

    /** No constraints, for a class without the section (which {@link ClassReader} reports). */
    static ConstraintsReader empty() {
        return new ConstraintsReader(null);
    }

    static ConstraintsReader read(XmlElement el, Reporter reporter) {
        ConstraintsReader reader = new ConstraintsReader(reporter);
        reader.readConstraints(el);
        return reader;
    }

    private void readConstraints(XmlElement el) {
        reporter.container(el);
        reporter.once(el.children("cardinality"), el);
        reporter.once(el.children("colocation"), el);
        for (XmlElement child : el.children()) {
            switch (child.name()) {
                case "cardinality" -> {
                    if (child == el.child("cardinality").orElseThrow()) {
                        readBounds(child);
                    }
                }
                case "colocation" -> {
                    if (child == el.child("colocation").orElseThrow()) {
                        readColocation(child);
                    }
                }
                default -> reporter.unexpected(child, el, "<cardinality> or <colocation>");
            }
        }
    }

    private void readBounds(XmlElement el) {
        reporter.container(el);
        for (XmlElement child : el.children()) {
            if (!child.name().equals("bound")) {
                reporter.unexpected(child, el, "<bound role=\"...\" min=\"...\" max=\"...\"/>");
                continue;
            }
            rule(child, Set.of("role", "min", "max"));
            Ref role = required(child, "role");
            Integer min = count(child, "min");
            Integer max = count(child, "max");
            if (child.attribute("min").isEmpty() && child.attribute("max").isEmpty()) {
                reporter.error(child, "neither min nor max; a <bound> limits the cardinality from below, above or both");
            }
            if (role != null) {
                bounds.add(new BoundDecl(role, min, max, child));
            }
        }
    }

    private void readColocation(XmlElement el) {
        reporter.container(el);
        for (XmlElement child : el.children()) {
            switch (child.name()) {
                case "parallel" -> {
                    rule(child, Set.of("role", "with"));
                    Ref role = required(child, "role");
                    List<Ref> with = list(child, "with");
                    if (role != null && with != null) {
                        parallel.add(new ParallelDecl(role, with, child));
                    }
                }
                case "exclusive" -> {
                    rule(child, Set.of("roles"));
                    List<Ref> names = list(child, "roles");
                    if (names != null) {
                        exclusive.add(new ExclusiveDecl(names, child));
                    }
                }
                case "secondary" -> {
                    rule(child, Set.of("role", "primary"));
                    Ref role = required(child, "role");
                    Ref primary = required(child, "primary");
                    if (role != null && primary != null) {
                        secondary.add(new SecondaryDecl(role, primary, child));
                    }
                }
                default -> reporter.unexpected(child, el, "<parallel>, <exclusive> or <secondary>");
            }
        }
    }

    /** A rule element: attributes only, no content. */
    private void rule(XmlElement el, Set<String> attributes) {
        reporter.attributes(el, attributes);
        reporter.noText(el);
        for (XmlElement child : el.children()) {
            reporter.error(child, "unexpected element; " + el.tag() + " takes attributes only");
        }
    }

    private Ref required(XmlElement el, String attribute) {
        String value = el.attribute(attribute).map(String::strip).orElse("");
        if (value.isEmpty()) {
            reporter.error(el, (el.attribute(attribute).isPresent() ? "empty" : "missing") + " attribute '" + attribute
                    + "'; " + el.tag() + " names a role in '" + attribute + "'");
            return null;
        }
        return new Ref(value, el);
    }

    private List<Ref> list(XmlElement el, String attribute) {
        if (el.attribute(attribute).isEmpty()) {
            reporter.error(el, "missing attribute '" + attribute + "'; " + el.tag() + " lists roles, separated by spaces, in '"
                    + attribute + "'");
            return null;
        }
        List<Ref> refs = new ArrayList<>();
        for (String role : MissionNames.split(el.attribute(attribute).get())) {
            refs.add(new Ref(role, el));
        }
        return refs;
    }

    private Integer count(XmlElement el, String attribute) {
        String value = el.attribute(attribute).orElse(null);
        if (value == null) {
            return null;
        }
        try {
            int n = Integer.parseInt(ParameterType.asciiWhole(value.strip()));
            if (n >= 0) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        reporter.error(el, attribute + "='" + value + "' is not a whole number >= 0; a cardinality bound is a count");
        return null;
    }
}
