package net.smc.core.mission;

import java.util.Set;
import java.util.regex.Pattern;

/** The rule for role names, shared by both files. */
final class Names {
    /** Letters, digits and {@code _}, from a letter: a role name is an element name and a policy URI segment. */
    private static final Pattern ROLE = Pattern.compile("[A-Za-z][A-Za-z0-9_]*");
    /** Names an instance file uses for its own sections, so no role may take them. */
    static final Set<String> RESERVED = Set.of("missionInstanceParameters", "missionClassParameters",
            "missionParameters", "constraints");

    private Names() {
    }

    /** Why {@code name} is not a role name, or {@code null} when it is one. */
    static String roleNameProblem(String name) {
        if (name.isEmpty()) {
            return "empty role name";
        }
        if (!ROLE.matcher(name).matches()) {
            return "invalid role name '" + name + "'; a role name is letters, digits and _, starting with a letter";
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
