package net.smc.policy.lang;

import java.io.UncheckedIOException;
import java.util.HashMap;
import java.util.Map;

/** Finds the text of a file named by {@code include "name"}. */
@FunctionalInterface
public interface IncludeResolver {

    /** A file's name (as diagnostics show it) and its text. */
    record Included(String source, String text) {
    }

    /**
     * Resolves {@code name}, written in unit {@code fromSource}.
     *
     * @return the file, or {@code null} when there is no such file
     * @throws java.io.UncheckedIOException when the file exists but cannot be read
     */
    Included resolve(String name, String fromSource);

    /** A resolver for units that may not include anything. */
    IncludeResolver NONE = (name, from) -> null;

    /**
     * A resolver that asks {@code resolver} once per name and unit, and then answers the same again
     * (a file found, not found, or unreadable): a unit checked once is given the same files when its
     * statements are parsed again to be run, even if the files change in between.
     */
    static IncludeResolver remembering(IncludeResolver resolver) {
        Map<String, Object> answers = new HashMap<>();
        return (name, fromSource) -> {
            Object answer = answers.computeIfAbsent(name + '\0' + fromSource, key -> {
                try {
                    Included found = resolver.resolve(name, fromSource);
                    return found == null ? Boolean.FALSE : found;
                } catch (UncheckedIOException e) {
                    return e;
                }
            });
            if (answer instanceof UncheckedIOException e) {
                throw e;
            }
            return answer instanceof Included found ? found : null;
        };
    }
}
