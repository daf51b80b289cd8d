package net.smc.demo;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionError;
import net.smc.core.mission.MissionException;
import net.smc.core.mission.MissionLoader;
import net.smc.core.security.Credential;
import net.smc.core.security.CredentialStatus;
import net.smc.core.security.SigningIdentity;
import net.smc.core.security.KeyFileException;
import net.smc.core.security.KeyFiles;
import net.smc.core.security.SigningKey;
import net.smc.core.security.TrustAnchor;
import net.smc.core.security.VerificationKey;
import net.smc.policy.api.PolicyRepository;

/**
 * The files {@code smc node} starts from, read and checked against each other: the vehicle's key and
 * credential, the mission authority's public key, and the mission. A file that cannot be read or is
 * refused stops the node ({@link Refused}, exit status 1), named by its option and its name as given.
 *
 * <p>The checks, in order: each file reads and has the right kind and form; the credential vouches
 * for the key; the authority signed the credential and it is valid now; the mission loads; the
 * credential is for that mission.
 */
final class NodeFiles {
    /** What the files say: who this vehicle is, whom it trusts, and the mission it serves. */
    record Node(SigningIdentity identity, TrustAnchor trust, Mission mission) {
    }

    /**
     * A file was refused: the node does not start. The message names the option, the file and the
     * problem; {@link #details()} are lines to print before it (a mission's errors). Control flow
     * only, so it has no stack trace.
     */
    static final class Refused extends Exception {
        private static final long serialVersionUID = 1L;
        private final List<String> details;

        Refused(String message) {
            this(message, List.of());
        }

        Refused(String message, List<String> details) {
            super(message, null, false, false);
            this.details = List.copyOf(details);
        }

        List<String> details() {
            return details;
        }
    }

    private final Path workingDir;
    private final List<Path> allowedDirs;

    /** Files given relative are read from {@code workingDir}. */
    NodeFiles(Path workingDir) {
        this(workingDir, List.of());
    }

    /**
     * Files given relative are read from {@code workingDir}; the mission's class may also be in one
     * of {@code allowedDirs} (relative ones from {@code workingDir}), not only beside its instance.
     */
    NodeFiles(Path workingDir, List<Path> allowedDirs) {
        this.workingDir = workingDir;
        this.allowedDirs = allowedDirs.stream().map(workingDir::resolve).toList();
    }

    /**
     * Reads and cross-checks the files.
     *
     * @param nowMillis the time the credential must be valid at, epoch ms
     */
    Node read(Path key, Path credential, Path authority, Path mission, PolicyRepository repository, long nowMillis)
            throws Refused {
        SigningKey signingKey = vehicleKey(key);
        Credential cred = readFile("--credential", credential, KeyFiles::parseCredential);
        VerificationKey authorityKey = readFile("--authority", authority, KeyFiles::parsePublicKey);
        if (!cred.vehicleKey().equals(signingKey.verificationKey())) {
            throw new Refused("--key " + key + " is not the key --credential " + credential + " vouches for: the "
                    + "credential of '" + cred.vehicleId() + "' names key " + cred.vehicleKey().id() + ", the private key's "
                    + "public half is " + signingKey.verificationKey().id());
        }
        CredentialStatus status = TrustAnchor.of(authorityKey).verify(cred, nowMillis);
        if (status != CredentialStatus.VALID) {
            throw new Refused("--credential " + credential + ": " + refusal(status, cred, authority, authorityKey, nowMillis));
        }
        Mission loaded = mission(mission, repository);
        if (!cred.mission().equals(loaded.instanceName())) {
            throw new Refused("--credential " + credential + " is for mission '" + cred.mission() + "', but --mission "
                    + mission + " is mission '" + loaded.instanceName() + "'");
        }
        return new Node(new SigningIdentity(signingKey, cred), new TrustAnchor(authorityKey, loaded.instanceName()), loaded);
    }

    private static String refusal(CredentialStatus status, Credential cred, Path authority, VerificationKey authorityKey,
                                  long nowMillis) {
        return switch (status) {
            case FOREIGN_AUTHORITY -> "issued by authority " + cred.authority() + ", not by the authority of --authority "
                    + authority + " (" + authorityKey.id() + ")";
            case BAD_SIGNATURE -> "the signature of authority " + authorityKey.id() + " does not verify (altered or forged)";
            case NOT_YET_VALID -> "not valid before " + Instant.ofEpochMilli(cred.notBeforeMillis()) + " (now "
                    + Instant.ofEpochMilli(nowMillis) + ")";
            case EXPIRED -> "expired at " + Instant.ofEpochMilli(cred.expiresMillis());
            case WRONG_MISSION, VALID -> "refused: " + status;   // a trust anchor without a mission checks none
        };
    }

    private Mission mission(Path given, PolicyRepository repository) throws Refused {
        Path file = readable("--mission", given);
        try {
            return new MissionLoader(repository, allowedDirs).load(file);
        } catch (IOException e) {
            throw new Refused("--mission " + given + ": cannot read it: " + e.getMessage());
        } catch (MissionException e) {
            int n = e.errors().size();
            throw new Refused("--mission " + given + ": the mission has " + n + (n == 1 ? " error" : " errors")
                    + "; the node does not start", e.errors().stream().map(MissionError::toString).toList());
        }
    }

    /** How a key file's text becomes a value; its errors name the file as given. */
    @FunctionalInterface
    private interface Parser<T> {
        T parse(String text, String source) throws KeyFileException;
    }

    private <T> T readFile(String option, Path given, Parser<T> parser) throws Refused {
        Path file = readable(option, given);
        try {
            return parser.parse(KeyFiles.read(file), given.toString());
        } catch (KeyFileException e) {
            throw new Refused(option + " " + e.getMessage());
        } catch (IOException e) {
            throw new Refused(option + " " + given + ": cannot read it: " + e.getMessage());
        }
    }

    /** A vehicle's private key, readable by its owner only. */
    private SigningKey vehicleKey(Path given) throws Refused {
        Path file = readable("--key", given);
        try {
            return KeyFiles.readPrivateKey(file, KeyFiles.Use.VEHICLE);
        } catch (KeyFileException e) {
            throw new Refused("--key " + e.getMessage());
        } catch (IOException e) {
            throw new Refused("--key " + given + ": cannot read it: " + e.getMessage());
        }
    }

    /** The file resolved against the working directory, if it is a readable regular file. */
    private Path readable(String option, Path given) throws Refused {
        Path file = workingDir.resolve(given);
        String problem = CellOptions.readProblem(file);
        if (problem != null) {
            throw new Refused(option + " " + given + ": cannot read it: " + problem);
        }
        return file;
    }
}
