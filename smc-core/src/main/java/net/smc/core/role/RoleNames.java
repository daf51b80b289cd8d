package net.smc.core.role;

/**
 * The naming rules of roles and of what they hold. Every role, task, policy, peer and event name
 * becomes an entry of a domain ({@code root/role/<name>/task/<task>}), so it is ASCII letters,
 * digits and {@code _}. A role name is also an element name of a mission instance and a segment of
 * policy URIs, so it starts with a letter: that is the one role-name rule, used by the mission
 * files ({@code net.smc.core.mission}) and by {@link Role} alike.
 */
public final class RoleNames {
    private RoleNames() {
    }

    /**
     * Why {@code name} is not a role name, or {@code null} when it is one: letters, digits and
     * {@code _}, starting with a letter.
     */
    public static String roleNameProblem(String name) {
        if (name == null || name.isEmpty()) {
            return "empty role name";
        }
        if (!valid(name) || !isLetter(name.charAt(0))) {
            return "invalid role name '" + name + "'; a role name is letters, digits and _, starting with a letter";
        }
        return null;
    }

    /**
     * Checks a role name: the domain-entry rule of {@link #check}, and a letter first.
     *
     * @param what what the name names, for the message ("role name", "role managed by 'commander'")
     * @throws IllegalArgumentException naming the value and the rule
     */
    static String checkRole(String what, String name) {
        check(what, name);
        if (!isLetter(name.charAt(0))) {
            throw new IllegalArgumentException(what + " is '" + name
                    + "'; a role name starts with a letter (it is also an element name of a mission instance)");
        }
        return name;
    }

    private static boolean isLetter(char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    }

    static boolean valid(String name) {
        if (name == null || name.isEmpty()) {
            return false;
        }
        for (int i = 0; i < name.length(); i++) {
            char c = name.charAt(i);
            if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) {
                return false;
            }
        }
        return true;
    }

    /**
     * Checks a name.
     *
     * @param what what the name names, for the message ("role name", "task name of role 'surveyor'")
     * @throws IllegalArgumentException naming the value and the rule
     */
    static String check(String what, String name) {
        if (!valid(name)) {
            throw new IllegalArgumentException(what + " is '" + name
                    + "'; it must be one or more ASCII letters, digits or _ (it becomes a domain entry)");
        }
        return name;
    }

    /** Checks that a selector is not empty (its shape is checked by the engine when it is sent). */
    static String checkSelector(String what, String selector) {
        if (selector == null || selector.isBlank() || !selector.strip().equals(selector)) {
            throw new IllegalArgumentException(what + " is '" + selector + "'; it must be a selector such as 'goTo:y:'");
        }
        return selector;
    }
}
