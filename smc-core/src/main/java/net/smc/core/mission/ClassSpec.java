package net.smc.core.mission;

import java.util.List;
import net.smc.core.capability.CapabilityRequirement;
import net.smc.core.xml.XmlElement;

/**
 * A mission class file as read (level 2), before its rules are checked: every name still carries
 * the element it came from, so that the checks can say where a wrong name is.
 *
 * @param root        the file's root element
 * @param name        the mission class name ({@code Reconnaissance}), or {@code null} when missing
 * @param parameters  the declared mission parameters, in file order
 * @param roles       the {@code <xxxBehaviour>} elements, in file order, one per role name
 * @param parallel    {@code <parallel>} colocation rules
 * @param exclusive   {@code <exclusive>} colocation rules
 * @param secondary   {@code <secondary>} colocation rules
 * @param bounds      {@code <bound>} cardinality constraints
 */
record ClassSpec(XmlElement root, String name, List<ParamDecl> parameters, List<RoleDecl> roles,
                 List<ParallelDecl> parallel, List<ExclusiveDecl> exclusive, List<SecondaryDecl> secondary,
                 List<BoundDecl> bounds) {

    /** A name written somewhere in the file. */
    record Ref(String name, XmlElement at) {
    }

    /** {@code <comTimeout>int</comTimeout>}; {@code type} is null when the file names no known type. */
    record ParamDecl(String name, ParameterType type, XmlElement at) {
    }

    /**
     * {@code <surveyorBehaviour>}.
     *
     * @param cardinality its {@code <cardinality>int</cardinality>}, or {@code null}: then the
     *                    instance sets no cardinality and the role has exactly one holder
     */
    record RoleDecl(String name, XmlElement at, XmlElement cardinality, List<Ref> manages,
                    CapabilityRequirement requirement, RoleInterface interfaces) {
        boolean hasCardinality() {
            return cardinality != null;
        }
    }

    record ParallelDecl(Ref role, List<Ref> with, XmlElement at) {
    }

    record ExclusiveDecl(List<Ref> roles, XmlElement at) {
    }

    record SecondaryDecl(Ref role, Ref primary, XmlElement at) {
    }

    /** {@code <bound role="surveyor" min="2" max="4"/>}: limits on the instance's cardinalities; null when absent. */
    record BoundDecl(Ref role, Integer min, Integer max, XmlElement at) {
    }

    RoleDecl role(String roleName) {
        return roles.stream().filter(r -> r.name().equals(roleName)).findFirst().orElse(null);
    }

    ParamDecl parameter(String parameterName) {
        return parameters.stream().filter(p -> p.name().equals(parameterName)).findFirst().orElse(null);
    }
}
