package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.util.Base64;
import java.util.List;
import net.smc.core.security.Claims;
import net.smc.core.security.Credential;
import net.smc.core.security.CredentialStatus;
import net.smc.core.security.KeyFiles;
import net.smc.core.security.SigningKey;
import net.smc.core.security.TrustAnchor;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code smc keys}, in-process on a temporary directory. */
class KeysCommandTest {
    @TempDir
    Path dir;

    private Smc smc;

    @BeforeEach
    void setUp() {
        smc = Smc.in(dir);
    }

    /** Makes an authority in keys/, a vehicle uav-1 in keys/, and issues it a 24 h credential. */
    private Smc.Result issueUav1() {
        assertEquals(0, smc.run("keys", "authority", "--out", "keys").status());
        assertEquals(0, smc.run("keys", "vehicle", "--id", "uav-1", "--out", "keys").status());
        return smc.run("keys", "issue", "--authority", "keys/authority.key", "--vehicle-pub", "keys/uav-1.pub",
                "--id", "uav-1", "--mission", "rescue", "--valid-for", "24h", "--out", "keys/uav-1.cred");
    }

    @Test
    void authority_writesAPrivateKeyOnlyItsOwnerCanRead_andAPublicKey() throws Exception {
        Smc.Result result = smc.run("keys", "authority", "--out", "keys");

        Path key = dir.resolve("keys/authority.key");
        Path pub = dir.resolve("keys/authority.pub");
        assertEquals(0, result.status(), result.err());
        assertEquals("", result.err());
        assertEquals("wrote " + key + " (private: keep it secret)", result.outLines().get(0));
        assertEquals("wrote " + pub, result.outLines().get(1));
        assertTrue(Files.readString(key).startsWith("smc-key v1 ed25519-private\n"));
        assertTrue(Files.readString(pub).startsWith("smc-key v1 ed25519-public\n"));
        assertEquals(KeyFiles.readPrivateKey(key).verificationKey(), KeyFiles.readPublicKey(pub));
        assertEquals("key id " + KeyFiles.readPublicKey(pub).id(), result.outLines().get(2));
        if (Files.getFileStore(key).supportsFileAttributeView("posix")) {
            assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(key)));
        }
    }

    @Test
    void vehicle_writesIdDotKeyAndIdDotPub() throws Exception {
        Smc.Result result = smc.run("keys", "vehicle", "--id", "uav-1", "--out", "keys");

        assertEquals(0, result.status(), result.err());
        assertEquals(KeyFiles.readPrivateKey(dir.resolve("keys/uav-1.key")).verificationKey(),
                KeyFiles.readPublicKey(dir.resolve("keys/uav-1.pub")));
        assertTrue(Files.readString(dir.resolve("keys/uav-1.pub")).contains("# vehicle uav-1\n"));
    }

    @Test
    void vehicleIdThatCannotNameAFile_isAUsageError() {
        Smc.Result result = smc.run("keys", "vehicle", "--id", "../evil", "--out", "keys");

        assertEquals(2, result.status());
        assertEquals("smc keys vehicle: --id '../evil' is not a vehicle id: it must be 1 to 64 of A-Z a-z 0-9 . _ -, "
                + "starting with a letter or digit (it names files)", result.errLines().get(0));
        assertFalse(Files.exists(dir.resolve("keys")));
    }

    @Test
    void issue_writesACredentialThatVerifiesAgainstTheAuthority_validFor24Hours() throws Exception {
        Smc.Result result = issueUav1();

        assertEquals(0, result.status(), result.err());
        Credential c = KeyFiles.readCredential(dir.resolve("keys/uav-1.cred"));
        assertEquals("uav-1", c.vehicleId());
        assertEquals("rescue", c.mission());
        assertEquals(KeyFiles.readPublicKey(dir.resolve("keys/uav-1.pub")), c.vehicleKey());
        assertEquals(24 * 3_600_000L, c.expiresMillis() - c.notBeforeMillis());
        TrustAnchor trust = TrustAnchor.of(KeyFiles.readPublicKey(dir.resolve("keys/authority.pub")));
        assertEquals(CredentialStatus.VALID, trust.verify(c, c.notBeforeMillis()));
        assertTrue(result.out().startsWith("wrote " + dir.resolve("keys/uav-1.cred") + ": credential of 'uav-1' for mission 'rescue', valid from "),
                result.out());
    }

    @Test
    void show_credentialCheckedAgainstItsAuthority_isValid() {
        issueUav1();

        Smc.Result result = smc.run("keys", "show", "keys/uav-1.cred", "--authority-pub", "keys/authority.pub");

        assertEquals(0, result.status(), result.err());
        assertTrue(result.outLines().contains("kind: a credential (smc-credential v1)"), result.out());
        assertTrue(result.outLines().contains("vehicle: uav-1"), result.out());
        assertTrue(result.outLines().contains("mission: rescue"), result.out());
        assertTrue(result.out().contains("status: valid (checked against " + dir.resolve("keys/authority.pub")), result.out());
    }

    @Test
    void show_credentialWithoutAuthority_saysItIsNotChecked() {
        issueUav1();

        Smc.Result result = smc.run("keys", "show", "keys/uav-1.cred");

        assertEquals(0, result.status());
        assertTrue(result.outLines().contains("status: not checked (give --authority-pub to check it)"), result.out());
    }

    @Test
    void show_credentialOfAnotherAuthority_isRefused_exitStatus1() throws Exception {
        issueUav1();
        assertEquals(0, smc.run("keys", "authority", "--out", "other").status());

        Smc.Result result = smc.run("keys", "show", "keys/uav-1.cred", "--authority-pub", "other/authority.pub");

        assertEquals(1, result.status());
        String issuer = KeyFiles.readPublicKey(dir.resolve("keys/authority.pub")).id().toString();
        String other = KeyFiles.readPublicKey(dir.resolve("other/authority.pub")).id().toString();
        assertTrue(result.out().contains("status: refused: issued by authority " + issuer + ", not by " + other), result.out());
    }

    @Test
    void show_expiredCredential_isRefused_exitStatus1() throws Exception {
        SecureRandom random = new SecureRandom();
        SigningKey authority = SigningKey.generate(random);
        SigningKey vehicle = SigningKey.generate(random);
        Credential old = Credential.issue(new Claims("uav-2", vehicle.verificationKey(), "rescue", 1_000, 2_000), authority);
        smc.file("old.cred", KeyFiles.credentialText(old, ""));
        smc.file("authority.pub", KeyFiles.publicKeyText(authority.verificationKey(), ""));

        Smc.Result result = smc.run("keys", "show", "old.cred", "--authority-pub", "authority.pub");

        assertEquals(1, result.status());
        assertTrue(result.out().contains("status: refused: expired at 1970-01-01T00:00:02Z"), result.out());
    }

    @Test
    void writtenPrivateKeys_areOwnerOnly_andSayWhatTheyAreFor() throws Exception {
        smc.run("keys", "authority", "--out", "keys");
        smc.run("keys", "vehicle", "--id", "v1", "--out", "keys");

        assertEquals("rw-------", java.nio.file.attribute.PosixFilePermissions.toString(
                Files.getPosixFilePermissions(dir.resolve("keys/authority.key"))));
        assertEquals("rw-------", java.nio.file.attribute.PosixFilePermissions.toString(
                Files.getPosixFilePermissions(dir.resolve("keys/v1.key"))));
        assertTrue(Files.readString(dir.resolve("keys/authority.key")).contains("\nuse: authority\n"));
        assertTrue(Files.readString(dir.resolve("keys/v1.key")).contains("\nuse: vehicle\n"));
    }

    @Test
    void privateKeyOthersMayRead_isRefused_namingTheModeAndTheChmod() throws Exception {
        smc.run("keys", "authority", "--out", "keys");
        smc.run("keys", "vehicle", "--id", "v1", "--out", "keys");
        for (String mode : List.of("rw-r--r--", "rw-rw-rw-", "rwxrwxrwx")) {
            Path key = dir.resolve("keys/authority.key");
            Files.setPosixFilePermissions(key, java.nio.file.attribute.PosixFilePermissions.fromString(mode));

            Smc.Result result = smc.run("keys", "issue", "--authority", "keys/authority.key", "--vehicle-pub", "keys/v1.pub",
                    "--id", "v1", "--mission", "M", "--valid-for", "1d", "--out", "v1.cred");

            assertEquals(1, result.status(), result.err());
            assertTrue(result.err().contains("private key file has mode "), result.err());
            assertTrue(result.err().contains("chmod 600 " + key), result.err());
            assertFalse(Files.exists(dir.resolve("v1.cred")));
        }
    }

    @Test
    void vehicleKeyGivenAsTheAuthority_isRefusedByItsKind() throws Exception {
        smc.run("keys", "vehicle", "--id", "v1", "--out", "keys");

        Smc.Result result = smc.run("keys", "issue", "--authority", "keys/v1.key", "--vehicle-pub", "keys/v1.pub",
                "--id", "v1", "--mission", "M", "--valid-for", "1d", "--out", "v1.cred");

        assertEquals(1, result.status(), result.err());
        assertTrue(result.err().contains("this is a vehicle's private key, not an authority's"), result.err());
    }

    @Test
    void privateKeyWrittenBeforeTheUseLine_isRecognisedByItsComment() throws Exception {
        net.smc.core.security.SigningKey authority = net.smc.core.security.SigningKey.generate(new java.security.SecureRandom());
        Path key = Path.of(smc.file("old-authority.key", KeyFiles.privateKeyText(authority, "mission authority")));
        Files.setPosixFilePermissions(key, java.nio.file.attribute.PosixFilePermissions.fromString("rw-------"));
        smc.run("keys", "vehicle", "--id", "v1", "--out", "keys");

        Smc.Result result = smc.run("keys", "issue", "--authority", "old-authority.key", "--vehicle-pub", "keys/v1.pub",
                "--id", "v1", "--mission", "M", "--valid-for", "1d", "--out", "v1.cred");

        assertEquals(0, result.status(), result.err());
    }

    @Test
    void show_privateKey_printsItsPublicHalf_neverThePrivateKey() throws Exception {
        smc.run("keys", "authority", "--out", "keys");
        String privateLine = Files.readString(dir.resolve("keys/authority.key")).lines().filter(l -> !l.startsWith("#") && !l.startsWith("use:")).toList().get(1);
        String seed = Base64.getEncoder().encodeToString(java.util.Arrays.copyOf(Base64.getDecoder().decode(privateLine), 32));

        Smc.Result result = smc.run("keys", "show", "keys/authority.key");

        assertEquals(0, result.status(), result.err());
        assertTrue(result.outLines().contains("kind: an Ed25519 private key (smc-key v1 ed25519-private)"), result.out());
        assertTrue(result.outLines().contains("public key id: " + KeyFiles.readPublicKey(dir.resolve("keys/authority.pub")).id()), result.out());
        assertFalse(result.out().contains(privateLine) || result.out().contains(seed.substring(0, 40)), "the private key is never shown");
    }

    @Test
    void publicKeyGivenAsTheAuthoritysPrivateKey_isRefused_namingTheFileAndTheExpectedHeader() {
        issueUav1();

        Smc.Result result = smc.run("keys", "issue", "--authority", "keys/authority.pub", "--vehicle-pub", "keys/uav-1.pub",
                "--id", "uav-1", "--mission", "rescue", "--valid-for", "1h", "--out", "x.cred");

        assertEquals(1, result.status());
        assertEquals("smc keys issue: " + dir.resolve("keys/authority.pub") + ": line 1 is 'smc-key v1 ed25519-public' "
                + "(that is the header of an Ed25519 public key file); expected 'smc-key v1 ed25519-private', "
                + "the header of an Ed25519 private key file", result.errLines().get(0));
        assertFalse(Files.exists(dir.resolve("x.cred")));
    }

    @Test
    void show_fileWithAnUnknownHeader_isRefused_namingTheFile() {
        String file = smc.file("notes.txt", "hello\n");

        Smc.Result result = smc.run("keys", "show", "notes.txt");

        assertEquals(1, result.status());
        assertEquals("smc keys show: " + file + ": line 1 is 'hello'; expected a key or credential header: "
                + "'smc-key v1 ed25519-private', 'smc-key v1 ed25519-public', 'smc-credential v1'", result.errLines().get(0));
    }

    @Test
    void existingOutput_isNotReplaced_withoutForce() throws Exception {
        smc.run("keys", "authority", "--out", "keys");
        String before = Files.readString(dir.resolve("keys/authority.key"));

        Smc.Result refused = smc.run("keys", "authority", "--out", "keys");
        assertEquals(1, refused.status());
        assertEquals("smc keys authority: " + dir.resolve("keys/authority.key") + " exists; use --force to replace it",
                refused.errLines().get(0));
        assertEquals(before, Files.readString(dir.resolve("keys/authority.key")));

        Smc.Result forced = smc.run("keys", "authority", "--out", "keys", "--force");
        assertEquals(0, forced.status(), forced.err());
        assertFalse(before.equals(Files.readString(dir.resolve("keys/authority.key"))));
    }

    @Test
    void badValidFor_isAUsageError() {
        issueUav1();

        Smc.Result result = smc.run("keys", "issue", "--authority", "keys/authority.key", "--vehicle-pub", "keys/uav-1.pub",
                "--id", "uav-1", "--mission", "rescue", "--valid-for", "24", "--out", "x.cred");

        assertEquals(2, result.status());
        assertTrue(result.errLines().get(0).contains("'24' is not a duration: a positive number and a unit, s, m, h or d, e.g. 24h or 30d"),
                result.err());
    }

    @Test
    void oversizeMission_isAUsageError_namingTheLimit() {
        issueUav1();

        Smc.Result result = smc.run("keys", "issue", "--authority", "keys/authority.key", "--vehicle-pub", "keys/uav-1.pub",
                "--id", "uav-1", "--mission", "m".repeat(65), "--valid-for", "1h", "--out", "x.cred");

        assertEquals(2, result.status());
        assertTrue(result.errLines().get(0).endsWith("is 65 bytes of UTF-8; the limit is 64"), result.err());
    }

    @Test
    void missingInputFile_isAUsageError() {
        Smc.Result result = smc.run("keys", "show", "missing.cred");

        assertEquals(2, result.status());
        assertEquals("smc keys show: cannot read 'missing.cred': no such file", result.errLines().get(0));
    }

    @Test
    void authorityPubWithAKeyFile_isAUsageError() {
        smc.run("keys", "authority", "--out", "keys");

        Smc.Result result = smc.run("keys", "show", "keys/authority.key", "--authority-pub", "keys/authority.pub");

        assertEquals(2, result.status());
        assertEquals("smc keys show: --authority-pub checks a credential, but 'keys/authority.key' holds an Ed25519 private key",
                result.errLines().get(0));
    }

    @Test
    void keysWithoutACommand_isAUsageError() {
        Smc.Result result = smc.run("keys");

        assertEquals(2, result.status());
        assertEquals("smc keys: no command given: use authority, vehicle, issue or show", result.errLines().get(0));
    }

    @Test
    void help_listsTheKeyCommands_andTheExitStatuses() {
        Smc.Result result = smc.run("keys", "--help");

        assertEquals(0, result.status());
        for (String command : new String[] {"authority", "vehicle", "issue", "show"}) {
            assertTrue(result.out().contains("  " + command + " "), result.out());
        }
        assertTrue(result.out().contains("Exit status:"), result.out());
    }

    /** A file that is not UTF-8 text is refused naming the file and its first bad byte. */
    @Test
    void showingAFileThatIsNotText_namesTheFileAndItsFirstBadByte() throws Exception {
        Path garbage = dir.resolve("garbage.bin");
        Files.write(garbage, new byte[] {'k', 'e', 'y', (byte) 0xFF, 0x00});

        Smc.Result result = smc.run("keys", "show", "garbage.bin");

        assertEquals(1, result.status(), result.err());
        assertTrue(result.err().contains("cannot read '" + garbage + "': not valid UTF-8: byte 0xFF at byte offset 3 (line 1)"),
                result.err());
    }

    /** --force replaces a key file, not a folder that has the key's name (an empty one went without a word). */
    @Test
    void forceDoesNotReplaceAFolderWithTheKeysName() throws Exception {
        Files.createDirectories(dir.resolve("keys/authority.key"));

        Smc.Result result = smc.run("keys", "authority", "--out", "keys", "--force");

        assertEquals(1, result.status(), result.err());
        assertTrue(result.err().contains("a folder of that name is there; --force replaces files only"), result.err());
        assertTrue(Files.isDirectory(dir.resolve("keys/authority.key")), "the folder is left as it was");
    }
}
