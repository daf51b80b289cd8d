package net.smc.core.mission;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import net.smc.core.capability.CapabilityRequirement;
import net.smc.core.mission.ClassSpec.ParamDecl;
import net.smc.core.mission.ClassSpec.Ref;
import net.smc.core.mission.ClassSpec.RoleDecl;
import net.smc.core.xml.XmlElement;

/**
 * Reads the structure of a mission class file (the paper's Table III, extended with requirements
 * and colocation rules; {@code missions/README.md} describes the format) and reports every element
 * that does not belong; {@link ConstraintsReader} reads the {@code <constraints>} section. Whether
 * the names it reads make sense together is {@link ClassRules}'s job.
 */
final class ClassReader {
    static final String BEHAVIOUR = "Behaviour";
    private static final String TOP = "<missionClassParameters>, <constraints>, <missionParameters> or a role's <xxxBehaviour>";

    private final Reporter reporter;
    private String name;
    private final List<ParamDecl> parameters = new ArrayList<>();
    private final List<RoleDecl> roles = new ArrayList<>();
    private ConstraintsReader constraints = ConstraintsReader.empty();

    private ClassReader(Reporter reporter) {
        this.reporter = reporter;
    }

    /** The class the file describes, or {@code null} (reported) when the file is no mission class at all. */
    static ClassSpec read(XmlElement root, Reporter reporter) {
        return new ClassReader(reporter).readRoot(root);
    }

    private ClassSpec readRoot(XmlElement root) {
        if (!root.name().equals("xml")) {
            reporter.error(root, "unexpected root element; a mission class file's root element is <xml>");
            return null;
        }
        if (root.child("missionInstanceParameters").isPresent() && root.child("missionClassParameters").isEmpty()) {
            reporter.error(root, "this is a mission instance, not a mission class; <missionClass href> names a mission class file");
            return null;
        }
        reporter.attributes(root, Set.of());
        reporter.noText(root);
        for (String section : List.of("missionClassParameters", "constraints", "missionParameters")) {
            reporter.once(root.children(section), root);
        }
        Set<String> seen = new LinkedHashSet<>();
        for (XmlElement child : root.children()) {
            boolean first = seen.add(child.name());
            switch (child.name()) {
                case "missionClassParameters" -> {
                    if (first) {
                        readClassParameters(child);
                    }
                }
                case "constraints" -> {
                    if (first) {
                        constraints = ConstraintsReader.read(child, reporter);
                    }
                }
                case "missionParameters" -> {
                    if (first) {
                        readParameters(child);
                    }
                }
                default -> {
                    if (child.name().endsWith(BEHAVIOUR)) {
                        readBehaviour(child);
                    } else {
                        reporter.unexpected(child, root, TOP);
                    }
                }
            }
        }
        if (!seen.contains("missionClassParameters")) {
            reporter.error(root, "no <missionClassParameters>; a mission class names itself in "
                    + "<missionClassParameters><missionClassName>");
        }
        if (!seen.contains("constraints")) {
            reporter.error(root, "no <constraints>; a mission class has a <constraints> section (it may be empty)");
        }
        if (!seen.contains("missionParameters")) {
            reporter.error(root, "no <missionParameters>; a mission class has a <missionParameters> section (it may be empty)");
        }
        return new ClassSpec(root, name, parameters, roles, constraints.parallel, constraints.exclusive, constraints.secondary,
                constraints.bounds);
    }

    private void readClassParameters(XmlElement el) {
        reporter.container(el);
        reporter.once(el.children("missionClassName"), el);
        for (XmlElement child : el.children()) {
            if (!child.name().equals("missionClassName")) {
                reporter.unexpected(child, el, "<missionClassName>");
            }
        }
        el.child("missionClassName").ifPresentOrElse(n -> {
            String text = reporter.leaf(n, "the mission class's name");
            name = text.isEmpty() ? null : text;
        }, () -> reporter.error(el, "no <missionClassName>; a mission class has a name"));
    }

    private void readParameters(XmlElement el) {
        reporter.container(el);
        Set<String> declared = new LinkedHashSet<>();
        for (XmlElement child : el.children()) {
            String typeName = reporter.leaf(child, "the parameter's type (" + ParameterType.names() + ")");
            if (!declared.add(child.name())) {
                reporter.error(child, "parameter '" + child.name() + "' is declared twice; each parameter is declared once");
                continue;
            }
            ParameterType type = null;
            if (!typeName.isEmpty()) {
                type = ParameterType.fromXmlName(typeName).orElse(null);
                if (type == null) {
                    reporter.textError(child, "unknown parameter type '" + typeName + "'; a parameter's type is one of "
                            + ParameterType.names());
                }
            }
            parameters.add(new ParamDecl(child.name(), type, child));
        }
    }

    private void readBehaviour(XmlElement el) {
        String role = el.name().substring(0, el.name().length() - BEHAVIOUR.length());
        String problem = MissionNames.roleNameProblem(role);
        if (problem != null) {
            reporter.error(el, problem + " (the element <xxxBehaviour> defines role xxx)");
        } else if (roles.stream().anyMatch(r -> r.name().equals(role))) {
            reporter.error(el, "role '" + role + "' is defined twice; each role has one " + el.tag());
            problem = "duplicate";
        }
        reporter.container(el);
        for (String part : List.of("cardinality", "requires", "roleManagement", "interface")) {
            reporter.once(el.children(part), el);
        }
        XmlElement cardinality = null;
        CapabilityRequirement requirement = CapabilityRequirement.none();
        List<Ref> manages = new ArrayList<>();
        RoleInterface interfaces = RoleInterface.NONE;
        for (XmlElement child : el.children()) {
            boolean first = el.children(child.name()).get(0) == child;
            switch (child.name()) {
                case "cardinality" -> {
                    if (first) {
                        cardinality = child;
                        readCardinalityType(child);
                    }
                }
                case "requires" -> {
                    if (first) {
                        requirement = readRequires(child);
                    }
                }
                case "roleManagement" -> {
                    if (first) {
                        readManagement(child, manages);
                    }
                }
                case "interface" -> {
                    if (first) {
                        interfaces = readInterface(child);
                    }
                }
                default -> reporter.unexpected(child, el, "<cardinality>, <requires>, <roleManagement> or <interface>");
            }
        }
        if (problem == null) {
            roles.add(new RoleDecl(role, el, cardinality, manages, requirement, interfaces));
        }
    }

    private void readCardinalityType(XmlElement el) {
        String type = reporter.leaf(el, "the type int");
        if (!type.isEmpty() && !type.equals("int")) {
            reporter.textError(el, "cardinality type '" + type + "'; a role's <cardinality> in a mission "
                    + "class is the type int (the instance gives the numbers)");
        }
    }

    private CapabilityRequirement readRequires(XmlElement el) {
        reporter.container(el);
        Set<String> resources = new LinkedHashSet<>();
        Set<String> tasks = new LinkedHashSet<>();
        for (XmlElement child : el.children()) {
            switch (child.name()) {
                case "resource" -> resources.add(reporter.leaf(child, "a resource name (motion, video ...)"));
                case "task" -> tasks.add(reporter.leaf(child, "a task name (Explorer ...)"));
                default -> reporter.unexpected(child, el, "<resource> or <task>");
            }
        }
        resources.remove("");
        tasks.remove("");
        return CapabilityRequirement.of(resources, tasks);
    }

    private void readManagement(XmlElement el, List<Ref> manages) {
        reporter.container(el);
        for (XmlElement child : el.children()) {
            if (!child.name().equals("manages")) {
                reporter.unexpected(child, el, "<manages>");
                continue;
            }
            String managed = reporter.leaf(child, "a role name");
            if (!managed.isEmpty()) {
                manages.add(new Ref(managed, child));
            }
        }
    }

    /** {@code <interface>}: the role's external interface (section II-B.2.A). */
    private RoleInterface readInterface(XmlElement el) {
        reporter.container(el);
        List<String> publishes = new ArrayList<>();
        List<String> subscribes = new ArrayList<>();
        List<RoleInterface.Offer> offers = new ArrayList<>();
        List<RoleInterface.Use> uses = new ArrayList<>();
        for (XmlElement child : el.children()) {
            switch (child.name()) {
                case "publishes" -> event(child, publishes);
                case "subscribes" -> event(child, subscribes);
                case "offers" -> {
                    String task = attributed(child, "task", "a task name (Aggregator ...)");
                    String selector = selector(child);
                    if (!task.isEmpty() && !selector.isEmpty()) {
                        offers.add(new RoleInterface.Offer(task, selector));
                    }
                }
                case "uses" -> {
                    String role = attributed(child, "role", "a role name");
                    String selector = selector(child);
                    if (!role.isEmpty() && !selector.isEmpty()) {
                        uses.add(new RoleInterface.Use(role, selector));
                    }
                }
                default -> reporter.unexpected(child, el, "<publishes>, <subscribes>, <offers> or <uses>");
            }
        }
        return new RoleInterface(publishes, subscribes, offers, uses);
    }

    private void event(XmlElement el, List<String> into) {
        String event = reporter.leaf(el, "an event name (hazardDetected ...)");
        if (event.isEmpty()) {
            return;
        }
        if (!event.matches("[A-Za-z][A-Za-z0-9_]*")) {
            reporter.textError(el, "event name '" + event + "'; an event name is a letter, then letters, digits or _");
        } else if (into.contains(event)) {
            reporter.textError(el, "event '" + event + "' is listed twice in " + el.tag());
        } else {
            into.add(event);
        }
    }

    /** The value of the one attribute {@code name} an element takes, reported when missing. */
    private String attributed(XmlElement el, String name, String what) {
        reporter.attributes(el, Set.of(name));
        String value = el.attribute(name).orElse("").trim();
        if (value.isEmpty()) {
            reporter.error(el, "missing attribute '" + name + "'; " + el.tag() + " names " + what);
        }
        return value;
    }

    private String selector(XmlElement el) {
        for (XmlElement child : el.children()) {
            reporter.error(child, "unexpected element; " + el.tag() + " holds text only");
        }
        String selector = el.text();
        if (selector.isEmpty()) {
            reporter.error(el, "empty; " + el.tag() + " must hold a PonderTalk selector (report:x:y: ...)");
        } else if (!selector.matches("[A-Za-z][A-Za-z0-9_]*|([A-Za-z][A-Za-z0-9_]*:)+")) {
            reporter.textError(el, "selector '" + selector + "'; a selector is a name (hazards) or keywords (report:x:y:)");
            return "";
        }
        return selector;
    }
}
