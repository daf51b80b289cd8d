package net.smc.core.mission;

import java.util.Set;
import net.smc.core.role.RoleNames;

/** The rule for role names in mission files ({@link RoleNames}'s, plus the reserved section names). */
final class MissionNames {
    /** Names an instance file uses for its own sections, so no role may take them. */
    static final Set<String> RESERVED = Set.of("missionInstanceParameters", "missionClassParameters",
            "missionParameters", "constraints");

    private MissionNames() {
    }

    /** Why {@code name} is not a role name, or {@code null} when it is one. */
    static String roleNameProblem(String name) {
        String problem = RoleNames.roleNameProblem(name);
        if (problem != null) {
            return problem;
        }
        if (RESERVED.contains(name)) {
            return "role name '" + name + "' is reserved; a role may not take the name of a section";
        }
        return null;
    }

    /** The names in a space-separated attribute ({@code with="surveyor hdetector"}). */
    static String[] split(String list) {
        String trimmed = list.strip();
        return trimmed.isEmpty() ? new String[0] : trimmed.split("\\s+");
    }
}
