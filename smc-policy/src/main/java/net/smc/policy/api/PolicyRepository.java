package net.smc.policy.api;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import net.smc.policy.lang.SourceFiles;

/**
 * A folder of PonderTalk files addressed by URI: {@code policy:/roles/surveyor/assign} is the file
 * {@code roles/surveyor/assign.p2} under the folder. A URI's segments are letters, digits,
 * {@code _} and {@code -}; nothing can name a file outside the folder.
 */
public final class PolicyRepository {
    /** The URI scheme of repository entries. */
    public static final String SCHEME = "policy:";

    private final Path root;

    public PolicyRepository(Path root) {
        this.root = root.toAbsolutePath().normalize();
    }

    public Path root() {
        return root;
    }

    /** Whether a string is written as a policy URI (it may still be invalid). */
    public static boolean isUri(String s) {
        return s.startsWith(SCHEME);
    }

    /**
     * The file a URI names.
     *
     * @throws IllegalArgumentException naming the URI and the rule it breaks
     */
    public Path pathOf(String uri) {
        if (!isUri(uri)) {
            throw new IllegalArgumentException("invalid policy URI '" + uri + "': it must start with 'policy:/'");
        }
        String rest = uri.substring(SCHEME.length());
        if (!rest.startsWith("/") || rest.length() < 2) {
            throw new IllegalArgumentException("invalid policy URI '" + uri + "': it must start with 'policy:/' and name a file");
        }
        String[] segments = rest.substring(1).split("/", -1);
        Path at = root;
        for (String segment : segments) {
            if (segment.isEmpty() || !segment.chars().allMatch(c -> Character.isLetterOrDigit(c) && c < 128 || c == '_' || c == '-')) {
                throw new IllegalArgumentException("invalid policy URI '" + uri + "': segment '" + segment
                        + "' must be letters, digits, _ or -");
            }
            at = at.resolve(segment);
        }
        return at.resolveSibling(at.getFileName() + ".p2");
    }

    /** The text of the file a URI names, if it exists. */
    public Optional<String> read(String uri) {
        Path file = pathOf(uri);
        if (!Files.isRegularFile(file)) {
            return Optional.empty();
        }
        try {
            return Optional.of(SourceFiles.decode(Files.readAllBytes(file)));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** A file under the folder by relative name, if it exists there (used for {@code include}). */
    public Optional<Path> find(String relative) {
        Path file = root.resolve(relative).normalize();
        return file.startsWith(root) && Files.isRegularFile(file) ? Optional.of(file) : Optional.empty();
    }

    /** Every URI in the repository, sorted. */
    public List<String> list() {
        List<String> uris = new ArrayList<>();
        if (!Files.isDirectory(root)) {
            return uris;
        }
        try (Stream<Path> files = Files.walk(root)) {
            files.filter(f -> f.toString().endsWith(".p2") && Files.isRegularFile(f)).sorted().forEach(f -> {
                String relative = root.relativize(f).toString().replace('\\', '/');
                uris.add(SCHEME + "/" + relative.substring(0, relative.length() - 3));
            });
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return uris;
    }
}
