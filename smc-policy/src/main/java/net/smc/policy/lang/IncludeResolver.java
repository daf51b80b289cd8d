package net.smc.policy.lang;

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
}
