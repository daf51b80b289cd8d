package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;

/** Paths of the domain tree ({@code root/event/alarm}, {@code /event/alarm}) to the objects they name. */
final class Paths {
    private Paths() {
    }

    /**
     * The object {@code path} names from {@code root}: absolute when it starts with '/', else from
     * root ({@code root/} optional).
     *
     * @throws PonderError {@code path not found 'x'} when a segment names nothing
     */
    static Object resolve(Domain root, String path) {
        String body = path.startsWith("/") ? path.substring(1) : path;
        if (body.equals("root")) {
            return root;
        }
        if (body.startsWith("root/") && !path.startsWith("/")) {
            body = body.substring(5);
        }
        Object at = root;
        for (String segment : body.split("/", -1)) {
            Object next = at instanceof Domain d ? d.get(segment) : null;
            if (next == null) {
                throw new PonderError("path not found '" + Numbers.abbreviate(path) + "'");
            }
            at = next;
        }
        return at;
    }
}
