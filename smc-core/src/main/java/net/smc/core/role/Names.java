package net.smc.core.role;

/**
 * The naming rule every role, task, policy, peer and event name must follow, because each becomes
 * an entry of a domain ({@code root/role/<name>/task/<task>}): ASCII letters, digits and {@code _}.
 */
final class Names {
    private Names() {
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
