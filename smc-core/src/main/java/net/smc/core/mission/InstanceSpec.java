package net.smc.core.mission;

import java.util.List;
import net.smc.core.mission.ClassSpec.Ref;
import net.smc.core.xml.XmlElement;

/**
 * A mission instance file as read (level 3), before it is checked against its class.
 *
 * @param root         the file's root element
 * @param name         the instance's name, or {@code null} when missing
 * @param classHref    the class file, relative to the instance file, or {@code null} when missing
 * @param className    the class name the instance expects, or {@code null} when missing
 * @param classAt      the {@code <missionClass>} element (the root when missing)
 * @param parametersAt the {@code <missionParameters>} element (the root when missing)
 * @param parameters   the parameter values, in file order, one per name
 * @param roles        the role elements, in file order, one per role name
 */
record InstanceSpec(XmlElement root, String name, String classHref, String className, XmlElement classAt,
                    XmlElement parametersAt, List<ParamValue> parameters, List<RoleEntry> roles) {

    /** {@code <comTimeout>500</comTimeout>}. */
    record ParamValue(String name, String text, XmlElement at) {
    }

    /**
     * {@code <surveyor>}: its cardinality (null when it has none), its role-mission's policy URIs
     * ({@code <policy>}) and its authorisations' ({@code <authorisation>}).
     */
    record RoleEntry(String name, XmlElement at, Cardinality cardinality, List<Ref> policies, List<Ref> authorisations) {
    }

    /**
     * {@code <cardinality><minimal>1</minimal><optimal>2</optimal></cardinality>}; a number is
     * null when it is missing or was reported as wrong.
     */
    record Cardinality(XmlElement at, Integer minimal, XmlElement minimalAt, Integer optimal, XmlElement optimalAt) {
    }

    RoleEntry role(String roleName) {
        return roles.stream().filter(r -> r.name().equals(roleName)).findFirst().orElse(null);
    }
}
