package net.smc.core.cell;

import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.zip.CRC32;

import net.smc.core.message.PolicyRef;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionRole;
import net.smc.policy.api.PolicyRepository;

/**
 * The policy files a cell holds, by URI, each with its version. The acting commander fills its
 * store from the policy repository and is the team's repository holder; every manager serves its
 * children from its own store, filled when it was assigned (an assignment names the policies of the
 * role and of the roles it manages, so that they travel down the management tree with it).
 *
 * <p>A version is derived from the text (a CRC-32, never 0), so two cells agree on it without a
 * registry, and a received text whose version does not match its content is refused.
 */
public final class PolicyStore {
    /** In a request, "the version you hold". */
    public static final int ANY_VERSION = 0;

    private final Map<String, Entry> entries = new HashMap<>();

    /** One held file. */
    public record Entry(String uri, int version, String text) {
    }

    /** The version of a text: a CRC-32 of its UTF-8 bytes, in 1 .. 2^31-1. */
    public static int versionOf(String text) {
        CRC32 crc = new CRC32();
        crc.update(text.getBytes(StandardCharsets.UTF_8));
        int v = (int) (crc.getValue() & 0x7fffffffL);
        return v == 0 ? 1 : v;
    }

    /**
     * Reads a file from the repository into the store.
     *
     * @throws IllegalArgumentException naming the URI when the repository has no such file
     */
    public Entry load(PolicyRepository repository, String uri) {
        String text = repository.read(uri).orElseThrow(() -> new IllegalArgumentException("policy '" + uri
                + "' is not in the repository at " + repository.root()));
        return put(uri, text);
    }

    /**
     * Reads every policy and authorisation file of {@code mission}'s roles from {@code repository}:
     * what the repository holder (the acting commander) serves the team from.
     *
     * @throws IllegalArgumentException naming the URI when the repository lacks one
     */
    public void loadMission(PolicyRepository repository, Mission mission) {
        for (MissionRole r : mission.roles()) {
            r.policies().forEach(uri -> load(repository, uri));
            r.authorisations().forEach(uri -> load(repository, uri));
        }
    }

    /** Holds {@code text} as the current version of {@code uri}. */
    public Entry put(String uri, String text) {
        Entry e = new Entry(Objects.requireNonNull(uri, "uri"), versionOf(text), text);
        entries.put(uri, e);
        return e;
    }

    /**
     * Holds a received file, if its version matches its content.
     *
     * @return whether it was accepted
     */
    public boolean accept(String uri, int version, String text) {
        if (versionOf(text) != version) {
            return false;
        }
        put(uri, text);
        return true;
    }

    /** The held file, if its version is {@code version} (or any, for {@link #ANY_VERSION}). */
    public Optional<Entry> get(String uri, int version) {
        Entry e = entries.get(uri);
        if (e == null || (version != ANY_VERSION && e.version() != version)) {
            return Optional.empty();
        }
        return Optional.of(e);
    }

    /** Whether the store holds exactly this reference. */
    public boolean has(PolicyRef ref) {
        return get(ref.uri(), ref.version()).isPresent();
    }

    /** The reference of a held file. */
    public Optional<PolicyRef> ref(String uri) {
        Entry e = entries.get(uri);
        return e == null ? Optional.empty() : Optional.of(new PolicyRef(uri, e.version()));
    }

    public int size() {
        return entries.size();
    }
}
