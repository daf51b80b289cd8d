package net.smc.core.mission;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import net.smc.core.message.WireFormat;
import net.smc.core.wire.StrictUtf8;
import net.smc.policy.api.PolicyRepository;
import net.smc.policy.lang.IncludeResolver;
import net.smc.policy.lang.Parser;
import net.smc.policy.lang.SourceFiles;
import net.smc.policy.lang.SyntaxError;
import net.smc.policy.lang.Unit;

/**
 * Whether a policy URI resolves in the repository and its file parses and fits one policy reply,
 * so that a mission never reaches a vehicle with a policy that cannot load or cannot be sent. The file is parsed, not run: running it needs
 * the role's managed objects. Includes resolve as a cell resolves them (beside the including file,
 * then in the repository), decoded as a cell decodes them; one that would leave the repository's
 * folder is refused here, so that a mission checked here never has a vehicle read other files. Answers are remembered per URI: roles often share a policy.
 */
final class PolicyCheck {
    private final PolicyRepository repository;
    private final Map<String, Optional<String>> problems = new HashMap<>();

    PolicyCheck(PolicyRepository repository) {
        this.repository = repository;
    }

    /** What is wrong with {@code uri} (a message ending in the rule), or empty when it resolves and parses. */
    Optional<String> problem(String uri) {
        return problems.computeIfAbsent(uri, this::check);
    }

    private Optional<String> check(String uri) {
        Path file;
        try {
            file = repository.pathOf(uri);
        } catch (IllegalArgumentException e) {
            return Optional.of(e.getMessage() + "; a role's policies are policy:/ URIs of the repository");
        }
        Optional<String> text;
        try {
            text = repository.read(uri);
        } catch (UncheckedIOException e) {
            return Optional.of("cannot read policy '" + uri + "': " + e.getCause().getMessage());
        }
        if (text.isEmpty()) {
            return Optional.of("policy '" + uri + "' not found: no file " + repository.root().relativize(file)
                    .toString().replace('\\', '/') + " in the policy repository; every policy URI must resolve in the repository");
        }
        int bytes = StrictUtf8.length(text.get());
        if (bytes > WireFormat.MAX_POLICY_TEXT) {
            return Optional.of("policy '" + uri + "' is " + bytes + " bytes of text; a policy file must be at most "
                    + WireFormat.MAX_POLICY_TEXT + " bytes, what one policy reply carries to a vehicle that takes "
                    + "the role (split it into several files)");
        }
        Map<String, Path> files = new HashMap<>(Map.of(uri, file));
        Unit unit;
        try {
            unit = Parser.parse(uri, text.get(), (name, from) -> include(name, from, files));
        } catch (UncheckedIOException e) {
            return Optional.of("cannot read a file policy '" + uri + "' includes: " + e.getCause().getMessage());
        }
        List<SyntaxError> errors = unit.errors();
        if (errors.isEmpty()) {
            return Optional.empty();
        }
        return Optional.of("policy '" + uri + "' does not parse: " + errors.get(0)
                + (errors.size() > 1 ? " (and " + (errors.size() - 1) + " more)" : "")
                + "; every policy must parse");
    }

    /** Whether {@code file} lies in the repository's folder (an include beside its file may not leave it). */
    private boolean inRepository(Path file) {
        Path root = repository.root().toAbsolutePath().normalize();
        return file.toAbsolutePath().normalize().startsWith(root);
    }

    private IncludeResolver.Included include(String name, String from, Map<String, Path> files) {
        Path including = files.get(from);
        Optional<Path> found;
        try {
            if (PolicyRepository.isUri(name)) {
                Path file = repository.pathOf(name);
                found = Files.isRegularFile(file) ? Optional.of(file) : Optional.empty();
            } else if (including != null && Files.isRegularFile(including.resolveSibling(name))) {
                Path sibling = including.resolveSibling(name).normalize();
                if (!inRepository(sibling)) {
                    throw new UncheckedIOException(new IOException("it is outside the policy repository "
                            + repository.root() + "; a policy includes files of the repository only"));
                }
                found = Optional.of(sibling);
            } else {
                found = repository.find(name);
            }
        } catch (IllegalArgumentException e) {  // also InvalidPathException
            return null;
        }
        if (found.isEmpty()) {
            return null;
        }
        try {
            String source = PolicyRepository.isUri(name) ? name : found.get().getFileName().toString();
            files.put(source, found.get());
            return new IncludeResolver.Included(source, SourceFiles.decode(Files.readAllBytes(found.get())));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
