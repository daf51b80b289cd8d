package net.smc.demo;

import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.time.Instant;
import java.util.EnumSet;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.LongSupplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import net.smc.core.security.Claims;
import net.smc.core.security.Credential;
import net.smc.core.security.CredentialStatus;
import net.smc.core.security.KeyFileException;
import net.smc.core.security.KeyFiles;
import net.smc.core.security.SigningKey;
import net.smc.core.security.TrustAnchor;
import net.smc.core.security.VerificationKey;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;
import picocli.CommandLine.TypeConversionException;

/**
 * {@code smc keys}: makes the key pairs of a mission authority and of vehicles, issues credentials,
 * and shows what a key or credential file holds. The file formats are those of {@link KeyFiles};
 * private keys are written with mode 600 where the file system has POSIX permissions.
 */
@Command(name = "keys", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        synopsisSubcommandLabel = "COMMAND",
        description = {
            "Makes and shows the keys and credentials of a team.",
            "A mission authority key pair signs credentials; each vehicle has a key pair and a credential "
                    + "(its id, its public key, the mission, a validity period) signed by the authority. "
                    + "Vehicles trust the authority's public key and check each other's credentials."},
        subcommands = {KeysCommand.Authority.class, KeysCommand.Vehicle.class, KeysCommand.Issue.class, KeysCommand.Show.class},
        exitCodeListHeading = "%nExit status:%n", exitCodeList = {
            "0:done (show: and the credential is valid, when checked)",
            "1:a file was refused (wrong header, bad content), a credential did not verify, an output file "
                    + "exists (without --force), or writing failed",
            "2:usage error: unknown option, a bad value, an input file that cannot be read"})
final class KeysCommand implements Callable<Integer> {
    /** Vehicle ids name files, so they are restricted to characters that are safe in a file name. */
    static final Pattern ID = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]{0,63}");
    private static final EnumSet<PosixFilePermission> OWNER_ONLY = EnumSet.of(PosixFilePermission.OWNER_READ, PosixFilePermission.OWNER_WRITE);

    private final Io io;
    private final LongSupplier clock;
    private final SecureRandom random;

    @Spec
    CommandSpec spec;

    KeysCommand(Io io) {
        this(io, System::currentTimeMillis, new SecureRandom());
    }

    /** A command with its own clock (epoch milliseconds) and randomness, for tests. */
    KeysCommand(Io io, LongSupplier clock, SecureRandom random) {
        this.io = io;
        this.clock = clock;
        this.random = random;
    }

    /** {@code smc keys} without a command. */
    @Override
    public Integer call() {
        throw new ParameterException(spec.commandLine(), "no command given: use authority, vehicle, issue or show");
    }

    /** {@code smc keys authority --out DIR}. */
    @Command(name = "authority", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
            description = "Makes a new mission authority key pair: DIR/authority.key (private, mode 600) and DIR/authority.pub.",
            exitCodeListHeading = "%nExit status:%n", exitCodeList = {
                "0:written", "1:a file exists (without --force), or writing failed", "2:usage error"})
    static final class Authority implements Callable<Integer> {
        @ParentCommand
        KeysCommand keys;

        @Spec
        CommandSpec spec;

        @Option(names = "--out", required = true, paramLabel = "DIR", description = "The directory to write to; made if missing.")
        Path out;

        @Option(names = "--force", description = "Replace files that exist.")
        boolean force;

        @Override
        public Integer call() {
            return keys.writeKeyPair(spec, out, "authority", KeyFiles.Use.AUTHORITY, "mission authority", force);
        }
    }

    /** {@code smc keys vehicle --id ID --out DIR}. */
    @Command(name = "vehicle", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
            description = "Makes a new vehicle key pair: DIR/ID.key (private, mode 600) and DIR/ID.pub.",
            exitCodeListHeading = "%nExit status:%n", exitCodeList = {
                "0:written", "1:a file exists (without --force), or writing failed", "2:usage error, or a bad --id"})
    static final class Vehicle implements Callable<Integer> {
        @ParentCommand
        KeysCommand keys;

        @Spec
        CommandSpec spec;

        @Option(names = "--id", required = true, paramLabel = "ID",
                description = "The vehicle's id: 1 to 64 of A-Z a-z 0-9 . _ -, starting with a letter or digit.")
        String id;

        @Option(names = "--out", required = true, paramLabel = "DIR", description = "The directory to write to; made if missing.")
        Path out;

        @Option(names = "--force", description = "Replace files that exist.")
        boolean force;

        @Override
        public Integer call() {
            checkId(spec, id);
            return keys.writeKeyPair(spec, out, id, KeyFiles.Use.VEHICLE, "vehicle " + id, force);
        }
    }

    /** {@code smc keys issue ...}. */
    @Command(name = "issue", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
            description = "Issues a credential: the authority signs that vehicle ID holds the key in --vehicle-pub "
                    + "and may join mission M from now for --valid-for.",
            exitCodeListHeading = "%nExit status:%n", exitCodeList = {
                "0:written", "1:a key file was refused, the output exists (without --force), or writing failed",
                "2:usage error: a bad --id, --mission or --valid-for, an input file that cannot be read"})
    static final class Issue implements Callable<Integer> {
        @ParentCommand
        KeysCommand keys;

        @Spec
        CommandSpec spec;

        @Option(names = "--authority", required = true, paramLabel = "FILE", description = "The authority's private key (authority.key).")
        Path authority;

        @Option(names = "--vehicle-pub", required = true, paramLabel = "FILE", description = "The vehicle's public key (ID.pub).")
        Path vehiclePub;

        @Option(names = "--id", required = true, paramLabel = "ID", description = "The vehicle's id, as for 'smc keys vehicle'.")
        String id;

        @Option(names = "--mission", required = true, paramLabel = "M", description = "The mission: 1 to 64 bytes of UTF-8.")
        String mission;

        @Option(names = "--valid-for", required = true, paramLabel = "DURATION", converter = DurationConverter.class,
                description = "How long from now it is valid: a number and s, m, h or d, e.g. 24h; at most 3650d.")
        long validForMillis;

        @Option(names = "--out", required = true, paramLabel = "FILE.cred", description = "The credential file to write.")
        Path out;

        @Option(names = "--force", description = "Replace the file if it exists.")
        boolean force;

        @Override
        public Integer call() {
            return keys.issue(this);
        }
    }

    /** {@code smc keys show FILE [--authority-pub FILE]}. */
    @Command(name = "show", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
            description = {"Prints what a key or credential file holds (never a private key itself).",
                "With --authority-pub, also checks a credential against that authority and the current time."},
            exitCodeListHeading = "%nExit status:%n", exitCodeList = {
                "0:shown (and the credential is valid, when checked)",
                "1:the file was refused, or the credential did not verify", "2:usage error"})
    static final class Show implements Callable<Integer> {
        @ParentCommand
        KeysCommand keys;

        @Spec
        CommandSpec spec;

        @Parameters(paramLabel = "FILE", description = "A key (.key, .pub) or credential (.cred) file.")
        Path file;

        @Option(names = "--authority-pub", paramLabel = "FILE", description = "The authority's public key, to check a credential against.")
        Path authorityPub;

        @Override
        public Integer call() {
            return keys.show(this);
        }
    }

    private int writeKeyPair(CommandSpec spec, Path dir, String name, KeyFiles.Use use, String comment, boolean force) {
        Path target = OutFolder.make(spec, io.workingDir(), dir);
        Path keyFile = target.resolve(name + ".key");
        Path pubFile = target.resolve(name + ".pub");
        String command = spec.qualifiedName();
        if (!force && (refuseExisting(command, keyFile) || refuseExisting(command, pubFile))) {
            return 1;
        }
        SigningKey key = SigningKey.generate(random);
        try {
            refuseFolder(keyFile);   // both before either is written: a failed pair leaves the old one whole
            refuseFolder(pubFile);
            writePrivate(keyFile, KeyFiles.privateKeyText(key, use, comment), force);
            write(pubFile, KeyFiles.publicKeyText(key.verificationKey(), comment), force);
        } catch (IOException e) {
            return failed(command, "cannot write in '" + target + "': " + OutFolder.reason(e));
        }
        io.stdout().println("wrote " + keyFile + " (private: keep it secret)");
        io.stdout().println("wrote " + pubFile);
        io.stdout().println("key id " + key.verificationKey().id());
        return 0;
    }

    private int issue(Issue o) {
        checkId(o.spec, o.id);
        List<Path> inputs = CellOptions.readableFiles(o.spec, io.workingDir(), List.of(o.authority, o.vehiclePub));
        Path out = io.workingDir().resolve(o.out);
        String command = o.spec.qualifiedName();
        if (!o.force && refuseExisting(command, out)) {
            return 1;
        }
        long now = clock.getAsLong();
        Claims claims;
        try {
            claims = new Claims(o.id, KeyFiles.readPublicKey(inputs.get(1)), o.mission, now, now + o.validForMillis);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(o.spec.commandLine(), e.getMessage());
        } catch (KeyFileException e) {
            return failed(command, e.getMessage());
        } catch (IOException e) {
            return failed(command, "cannot read '" + inputs.get(1) + "': " + OutFolder.reason(e));
        }
        SigningKey authority;
        try {
            authority = KeyFiles.readPrivateKey(inputs.get(0), KeyFiles.Use.AUTHORITY);
        } catch (KeyFileException e) {
            return failed(command, e.getMessage());
        } catch (IOException e) {
            return failed(command, "cannot read '" + inputs.get(0) + "': " + OutFolder.reason(e));
        }
        try {
            Credential credential = Credential.issue(claims, authority);
            write(out, KeyFiles.credentialText(credential, "vehicle " + o.id + ", mission " + o.mission), o.force);
            io.stdout().println("wrote " + out + ": credential of '" + o.id + "' for mission '" + o.mission + "', valid from "
                    + Instant.ofEpochMilli(claims.notBeforeMillis()) + " until " + Instant.ofEpochMilli(claims.expiresMillis())
                    + ", issued by authority " + authority.verificationKey().id());
            return 0;
        } catch (IOException e) {
            return failed(command, "cannot write '" + out + "': " + OutFolder.reason(e));
        }
    }

    private int show(Show o) {
        List<Path> files = o.authorityPub == null ? List.of(o.file) : List.of(o.file, o.authorityPub);
        List<Path> inputs = CellOptions.readableFiles(o.spec, io.workingDir(), files);
        Path file = inputs.get(0);
        String command = o.spec.qualifiedName();
        try {
            String text = KeyFiles.read(file);
            KeyFiles.Kind kind = KeyFiles.kindOf(text, file.toString());
            if (o.authorityPub != null && kind != KeyFiles.Kind.CREDENTIAL) {
                throw new ParameterException(o.spec.commandLine(), "--authority-pub checks a credential, but '" + o.file + "' holds "
                        + kind.description());
            }
            io.stdout().println("file: " + file);
            io.stdout().println("kind: " + kind.description() + " (" + kind.header() + ")");
            switch (kind) {
                case PRIVATE_KEY -> {
                    KeyFiles.checkPrivate(file);
                    io.stdout().println("use: " + KeyFiles.useOf(text, file.toString()).word());
                    printKey("public key", KeyFiles.parsePrivateKey(text, file.toString()).verificationKey());
                }
                case PUBLIC_KEY -> printKey("public key", KeyFiles.parsePublicKey(text, file.toString()));
                case CREDENTIAL -> {
                    return showCredential(KeyFiles.parseCredential(text, file.toString()),
                            o.authorityPub == null ? null : inputs.get(1));
                }
            }
            return 0;
        } catch (KeyFileException e) {
            return failed(command, e.getMessage());
        } catch (IOException e) {
            return failed(command, "cannot read '" + file + "': " + OutFolder.reason(e));
        }
    }

    private int showCredential(Credential c, Path authorityPub) throws IOException, KeyFileException {
        io.stdout().println("vehicle: " + c.vehicleId());
        printKey("vehicle key", c.vehicleKey());
        io.stdout().println("mission: " + c.mission());
        io.stdout().println("not before: " + Instant.ofEpochMilli(c.notBeforeMillis()));
        io.stdout().println("expires: " + Instant.ofEpochMilli(c.expiresMillis()));
        io.stdout().println("authority key id: " + c.authority());
        if (authorityPub == null) {
            io.stdout().println("status: not checked (give --authority-pub to check it)");
            return 0;
        }
        VerificationKey authority = KeyFiles.readPublicKey(authorityPub);
        long now = clock.getAsLong();
        CredentialStatus status = TrustAnchor.of(authority).verify(c, now);
        io.stdout().println("status: " + describe(status, c, authority) + " (checked against " + authorityPub + " at "
                + Instant.ofEpochMilli(now) + ")");
        return status == CredentialStatus.VALID ? 0 : 1;
    }

    private static String describe(CredentialStatus status, Credential c, VerificationKey authority) {
        return switch (status) {
            case VALID -> "valid";
            case FOREIGN_AUTHORITY -> "refused: issued by authority " + c.authority() + ", not by " + authority.id();
            case BAD_SIGNATURE -> "refused: the authority's signature does not verify (altered or forged)";
            case NOT_YET_VALID -> "refused: not valid before " + Instant.ofEpochMilli(c.notBeforeMillis());
            case EXPIRED -> "refused: expired at " + Instant.ofEpochMilli(c.expiresMillis());
            case WRONG_MISSION -> "refused: wrong mission";
        };
    }

    private void printKey(String label, VerificationKey key) {
        io.stdout().println(label + ": " + java.util.Base64.getEncoder().encodeToString(key.bytes()));
        io.stdout().println(label.replace("key", "key id") + ": " + key.id());
    }

    private boolean refuseExisting(String command, Path file) {
        if (Files.exists(file)) {
            failed(command, file + " exists; use --force to replace it");
            return true;
        }
        return false;
    }

    private int failed(String command, String message) {
        io.stderr().println(command + ": " + message);
        return 1;
    }

    private static void checkId(CommandSpec spec, String id) {
        if (!ID.matcher(id).matches()) {
            throw new ParameterException(spec.commandLine(), "--id '" + id + "' is not a vehicle id: it must be 1 to 64 of "
                    + "A-Z a-z 0-9 . _ -, starting with a letter or digit (it names files)");
        }
    }

    /** --force replaces a file, never a folder (an empty one would go without a word). */
    private static void refuseFolder(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new java.nio.file.FileSystemException(file.toString(), null, "a folder of that name is there; --force replaces files only");
        }
    }

    /** Writes a private key readable by its owner only, where the file system has POSIX permissions. */
    private static void writePrivate(Path file, String text, boolean replace) throws IOException {
        refuseFolder(file);
        if (replace) {
            Files.deleteIfExists(file);
        }
        try {
            Files.createFile(file, PosixFilePermissions.asFileAttribute(OWNER_ONLY));
        } catch (UnsupportedOperationException e) {
            Files.createFile(file);
        }
        Files.writeString(file, text, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING);
    }

    private static void write(Path file, String text, boolean replace) throws IOException {
        refuseFolder(file);
        if (replace) {
            Files.writeString(file, text);
        } else {
            try {
                Files.writeString(file, text, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
            } catch (FileAlreadyExistsException e) {
                throw new IOException(file + " appeared while writing", e);
            }
        }
    }

    /** A duration as a number and a unit: {@code 90s}, {@code 30m}, {@code 24h}, {@code 7d}; answers milliseconds. */
    static final class DurationConverter implements ITypeConverter<Long> {
        private static final Pattern FORM = Pattern.compile("([1-9][0-9]{0,6})([smhd])");
        private static final long MAX_MILLIS = 3650L * 86_400_000L;

        @Override
        public Long convert(String value) {
            Matcher m = FORM.matcher(value);
            if (!m.matches()) {
                throw new TypeConversionException("'" + value + "' is not a duration: a positive number and a unit, "
                        + "s, m, h or d, e.g. 24h or 30d");
            }
            long unit = switch (m.group(2)) {
                case "s" -> 1_000L;
                case "m" -> 60_000L;
                case "h" -> 3_600_000L;
                default -> 86_400_000L;
            };
            long millis = Long.parseLong(m.group(1)) * unit;
            if (millis > MAX_MILLIS) {
                throw new TypeConversionException("'" + value + "' is longer than 3650d, the longest validity");
            }
            return millis;
        }
    }
}
