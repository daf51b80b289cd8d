package net.smc.core.mission;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import net.smc.core.mission.ClassSpec.Ref;
import net.smc.core.mission.InstanceSpec.Cardinality;
import net.smc.core.mission.InstanceSpec.ParamValue;
import net.smc.core.mission.InstanceSpec.RoleEntry;
import net.smc.core.xml.XmlElement;

/**
 * Reads the structure of a mission instance file and checks what it can alone: required sections,
 * cardinalities that are numbers with minimal at most optimal. {@link InstanceRules} checks it
 * against its class and the policy repository.
 */
final class InstanceReader {
    private final Reporter reporter;
    private String name;
    private String classHref;
    private String className;
    private XmlElement classAt;
    private XmlElement parametersAt;
    private final List<ParamValue> parameters = new ArrayList<>();
    private final List<RoleEntry> roles = new ArrayList<>();

    private InstanceReader(Reporter reporter) {
        this.reporter = reporter;
    }

    /** The instance the file describes, or {@code null} (reported) when it is no mission instance at all. */
    static InstanceSpec read(XmlElement root, Reporter reporter) {
        return new InstanceReader(reporter).readRoot(root);
    }

    private InstanceSpec readRoot(XmlElement root) {
        if (!root.name().equals("xml")) {
            reporter.error(root, "unexpected root element; a mission instance file's root element is <xml>");
            return null;
        }
        if (root.child("missionClassParameters").isPresent() && root.child("missionInstanceParameters").isEmpty()) {
            reporter.error(root, "this is a mission class, not a mission instance; an instance has "
                    + "<missionInstanceParameters> with a <missionClass href=\"...\"> naming its class");
            return null;
        }
        reporter.attributes(root, Set.of());
        reporter.noText(root);
        reporter.once(root.children("missionInstanceParameters"), root);
        reporter.once(root.children("missionParameters"), root);
        classAt = root;
        parametersAt = root;
        Set<String> seen = new HashSet<>();
        for (XmlElement child : root.children()) {
            boolean first = seen.add(child.name());
            switch (child.name()) {
                case "missionInstanceParameters" -> {
                    if (first) {
                        readInstanceParameters(child);
                    }
                }
                case "missionParameters" -> {
                    if (first) {
                        readParameters(child);
                    }
                }
                default -> readRole(child, first);
            }
        }
        if (!seen.contains("missionInstanceParameters")) {
            reporter.error(root, "no <missionInstanceParameters>; an instance names itself and its class there");
        }
        if (!seen.contains("missionParameters")) {
            reporter.error(root, "no <missionParameters>; a mission instance has a <missionParameters> section "
                    + "(it may be empty)");
        }
        return new InstanceSpec(root, name, classHref, className, classAt, parametersAt, parameters, roles);
    }

    private void readInstanceParameters(XmlElement el) {
        reporter.container(el);
        reporter.once(el.children("missionInstanceName"), el);
        reporter.once(el.children("missionClass"), el);
        for (XmlElement child : el.children()) {
            if (!child.name().equals("missionInstanceName") && !child.name().equals("missionClass")) {
                reporter.unexpected(child, el, "<missionInstanceName> or <missionClass>");
            }
        }
        el.child("missionInstanceName").ifPresentOrElse(n -> {
            String text = reporter.leaf(n, "the mission instance's name");
            name = text.isEmpty() ? null : text;
        }, () -> reporter.error(el, "no <missionInstanceName>; a mission instance has a name"));
        el.child("missionClass").ifPresentOrElse(this::readClassReference,
                () -> reporter.error(el, "no <missionClass>; an instance names its class as "
                        + "<missionClass href=\"FILE.class.xml\">ClassName</missionClass>"));
    }

    private void readClassReference(XmlElement el) {
        classAt = el;
        for (XmlElement child : el.children()) {
            reporter.error(child, "unexpected element; " + el.tag() + " holds text only");
        }
        reporter.attributes(el, Set.of("href"));
        String href = el.attribute("href").map(String::strip).orElse("");
        if (href.isEmpty()) {
            reporter.error(el, (el.attribute("href").isPresent() ? "empty" : "missing") + " attribute 'href'; "
                    + "<missionClass href=\"FILE.class.xml\"> names the class file, relative to this file");
        } else {
            classHref = href;
        }
        if (el.text().isEmpty()) {
            reporter.error(el, "empty; <missionClass> holds the name of the mission class");
        } else {
            className = el.text();
        }
    }

    private void readParameters(XmlElement el) {
        parametersAt = el;
        reporter.container(el);
        Set<String> given = new HashSet<>();
        for (XmlElement child : el.children()) {
            String text = reporter.leaf(child, null);
            if (!given.add(child.name())) {
                reporter.error(child, "parameter '" + child.name() + "' is given twice; each parameter has one value");
            } else {
                parameters.add(new ParamValue(child.name(), text, child));
            }
        }
    }

    private void readRole(XmlElement el, boolean first) {
        String problem = MissionNames.roleNameProblem(el.name());
        if (problem != null) {
            reporter.error(el, problem);
        } else if (!first) {
            reporter.error(el, "role '" + el.name() + "' appears twice; each role has one element in an instance");
        }
        reporter.container(el);
        reporter.once(el.children("cardinality"), el);
        Cardinality cardinality = null;
        List<Ref> policies = new ArrayList<>();
        List<Ref> authorisations = new ArrayList<>();
        Set<String> uris = new LinkedHashSet<>();
        for (XmlElement child : el.children()) {
            switch (child.name()) {
                case "cardinality" -> {
                    if (cardinality == null) {
                        cardinality = readCardinality(child);
                    }
                }
                case "policy", "authorisation" -> {
                    String uri = reporter.leaf(child, "a policy URI (policy:/roles/" + el.name() + "/NAME)");
                    if (!uri.isEmpty() && !uris.add(uri)) {
                        reporter.textError(child, "policy '" + uri + "' is listed twice for role '" + el.name()
                                + "'; each policy file is listed once");
                    } else if (!uri.isEmpty()) {
                        (child.name().equals("policy") ? policies : authorisations).add(new Ref(uri, child));
                    }
                }
                default -> reporter.unexpected(child, el, "<cardinality>, <policy> or <authorisation>");
            }
        }
        if (problem == null && first) {
            roles.add(new RoleEntry(el.name(), el, cardinality, policies, authorisations));
        }
    }

    private Cardinality readCardinality(XmlElement el) {
        reporter.container(el);
        reporter.once(el.children("minimal"), el);
        reporter.once(el.children("optimal"), el);
        for (XmlElement child : el.children()) {
            if (!child.name().equals("minimal") && !child.name().equals("optimal")) {
                reporter.unexpected(child, el, "<minimal> and <optimal>");
            }
        }
        XmlElement minimalAt = el.child("minimal").orElse(null);
        XmlElement optimalAt = el.child("optimal").orElse(null);
        Integer minimal = count(el, minimalAt, "minimal", 0);
        Integer optimal = count(el, optimalAt, "optimal", 1);
        if (minimal != null && optimal != null && minimal > optimal) {
            reporter.textError(minimalAt, "minimal " + minimal + " is more than optimal " + optimal
                    + "; the minimal cardinality is at most the reasonably-optimal one");
        }
        return new Cardinality(el, minimal, minimalAt, optimal, optimalAt);
    }

    private Integer count(XmlElement cardinality, XmlElement el, String what, int least) {
        if (el == null) {
            reporter.error(cardinality, "no <" + what + ">; a role's cardinality gives <minimal> and <optimal>");
            return null;
        }
        String text = reporter.leaf(el, "a whole number");
        if (text.isEmpty()) {
            return null;
        }
        try {
            int n = Integer.parseInt(ParameterType.asciiWhole(text));
            if (n >= least) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        reporter.textError(el, "'" + text + "' is not a whole number >= " + least + "; " + (least == 0
                ? "a minimal cardinality counts vehicles, 0 or more"
                : "an optimal cardinality is at least 1 (a role nobody may hold would not belong in the mission)"));
        return null;
    }
}
