package net.smc.policy.runtime;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;

import net.smc.policy.api.PolicyRepository;
import net.smc.policy.api.PonderError;
import net.smc.policy.lang.IncludeResolver;
import net.smc.policy.lang.ParsedUnits;
import net.smc.policy.lang.Parser;
import net.smc.policy.lang.SyntaxError;
import net.smc.policy.lang.Unit;
import net.smc.policy.lang.SourceFiles;

/**
 * Where a cell's units come from on disk: the file each unit was read from, by its source name,
 * so that a name a unit reads or includes resolves against that unit's folder first, then as a
 * plain path (for a unit with no file), then in the policy repository; a {@code policy:} URI is the
 * repository's. A file of the repository names files of the repository only (its folder's others
 * outside it are refused). Files are read within the unit size limit.
 */
final class UnitFiles {
    private final PolicyRepository repository;
    private final int maxChars;
    private final Map<String, Path> files = new HashMap<>();

    /** @param repository the policy repository, or null when none is configured */
    UnitFiles(PolicyRepository repository, int maxChars) {
        this.repository = repository;
        this.maxChars = maxChars;
    }

    private boolean inRepository(Path file) {
        return file.startsWith(repository.root().toAbsolutePath().normalize());
    }

    /** Notes that the unit named {@code source} was read from {@code file}. */
    void remember(String source, Path file) {
        files.put(source, file.toAbsolutePath().normalize());
    }

    /**
     * The text of a file that a unit names (resolved as {@code read:} resolves it).
     *
     * @throws PonderError {@code cannot read 'x': file not found}
     */
    String readText(String name, String fromSource) {
        IncludeResolver.Included file;
        try {
            file = read(name, fromSource);
        } catch (UncheckedIOException e) {
            throw new PonderError("cannot read '" + name + "': " + e.getCause().getMessage());
        }
        if (file == null) {
            throw new PonderError("cannot read '" + name + "': file not found");
        }
        return file.text();
    }

    /** Reads the file or policy URI {@code name}, relative to the folder of {@code fromSource}; null when there is none. */
    IncludeResolver.Included read(String name, String fromSource) {
        Path file;
        if (PolicyRepository.isUri(name)) {
            if (repository == null) {
                throw new PonderError("cannot read '" + name + "': no policy repository is configured");
            }
            try {
                file = repository.pathOf(name);
            } catch (IllegalArgumentException e) {
                throw new PonderError(e.getMessage());
            }
        } else {
            file = locate(name, fromSource).orElse(null);
        }
        if (file == null || !Files.isRegularFile(file)) {
            return null;
        }
        try {
            String text = SourceFiles.read(file, maxChars);
            String source = PolicyRepository.isUri(name) ? name : file.getFileName().toString();
            remember(source, file);
            return new IncludeResolver.Included(source, text);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Parses a unit's text, its includes resolved by {@link #resolveInclude}, and reports each
     * syntax error. With {@code shared} (the parses the cells of one process share; null: none), a
     * unit that parsed before from the same text without errors or includes is taken from it.
     */
    Unit parse(String source, String text, ParsedUnits shared, Consumer<SyntaxError> report) {
        if (shared != null) {
            Unit kept = shared.find(source, text);
            if (kept != null) {
                return kept;   // parsed without errors or includes: nothing to report
            }
        }
        boolean[] included = {false};
        Unit unit = Parser.parse(source, text, (name, from) -> {
            included[0] = true;
            return resolveInclude(name, from);
        });
        unit.errors().forEach(report);
        return shared == null ? unit : shared.keep(unit, text, included[0]);
    }

    /** An include's file for the parser, whose resolver reports problems as I/O errors. */
    IncludeResolver.Included resolveInclude(String name, String fromSource) {
        try {
            return read(name, fromSource);
        } catch (PonderError e) {
            throw new UncheckedIOException(new IOException(e.getMessage()));
        }
    }

    private Optional<Path> locate(String name, String fromSource) {
        try {
            return locateFile(name, fromSource);
        } catch (java.nio.file.InvalidPathException e) {
            return Optional.empty();
        }
    }

    private Optional<Path> locateFile(String name, String fromSource) {
        Path from = files.get(fromSource);
        if (from != null) {
            Path sibling = from.resolveSibling(name).toAbsolutePath().normalize();
            if (Files.isRegularFile(sibling)) {
                if (repository != null && inRepository(from) && !inRepository(sibling)) {
                    // a file of the repository (a role's policy, and what it includes) reads only the repository
                    throw new UncheckedIOException(new IOException("it is outside the policy repository; a policy"
                            + " of the repository includes and reads files of the repository only"));
                }
                return Optional.of(sibling);
            }
        }
        Path plain = Path.of(name);
        if (from == null && Files.isRegularFile(plain)) {
            return Optional.of(plain);
        }
        return repository == null ? Optional.empty() : repository.find(name);
    }
}
