package net.smc.core.security;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class KeyFilesTest {
    private final Team team = new Team(2);

    @TempDir
    Path dir;

    @Test
    void privateKey_roundTrips_withItsComment() throws Exception {
        String text = KeyFiles.privateKeyText(team.authority, "mission authority");

        assertTrue(text.startsWith("smc-key v1 ed25519-private\n# mission authority\n"), text);
        assertEquals(team.authority, KeyFiles.parsePrivateKey(text, "a.key"));
        assertEquals(team.authority.verificationKey(), KeyFiles.parsePrivateKey(text, "a.key").verificationKey());
    }

    @Test
    void publicKey_andCredential_roundTripThroughFiles() throws Exception {
        SigningIdentity id = team.identity("uav-1");
        Path pub = Files.writeString(dir.resolve("uav-1.pub"), KeyFiles.publicKeyText(id.key().verificationKey(), "uav-1"));
        Path cred = Files.writeString(dir.resolve("uav-1.cred"), KeyFiles.credentialText(id.credential(), "uav-1"));

        assertEquals(id.key().verificationKey(), KeyFiles.readPublicKey(pub));
        assertEquals(id.credential(), KeyFiles.readCredential(cred));
        assertEquals(KeyFiles.Kind.CREDENTIAL, KeyFiles.kindOf(Files.readString(cred), cred.toString()));
    }

    @Test
    void publicKeyGivenAsPrivate_isRefused_namingTheFileAndTheExpectedHeader() {
        String text = KeyFiles.publicKeyText(team.authority.verificationKey(), "");

        KeyFileException e = assertThrows(KeyFileException.class, () -> KeyFiles.parsePrivateKey(text, "/keys/authority.pub"));

        assertEquals("/keys/authority.pub: line 1 is 'smc-key v1 ed25519-public' (that is the header of an Ed25519 public key file);"
                + " expected 'smc-key v1 ed25519-private', the header of an Ed25519 private key file", e.getMessage());
    }

    @Test
    void unknownHeader_isRefused() {
        KeyFileException e = assertThrows(KeyFileException.class, () -> KeyFiles.parseCredential("-----BEGIN PRIVATE KEY-----\nAAAA\n", "x.cred"));

        assertEquals("x.cred: line 1 is '-----BEGIN PRIVATE KEY-----'; expected 'smc-credential v1', the header of a credential file",
                e.getMessage());
    }

    @Test
    void wrongLength_isRefused_namingTheLine() {
        KeyFileException e = assertThrows(KeyFileException.class,
                () -> KeyFiles.parsePublicKey("smc-key v1 ed25519-public\n# c\nAAAA\n", "k.pub"));

        assertEquals("k.pub: line 3 holds 3 bytes; an Ed25519 public key file holds 32", e.getMessage());
    }

    @Test
    void notBase64_isRefused() {
        KeyFileException e = assertThrows(KeyFileException.class, () -> KeyFiles.parsePublicKey("smc-key v1 ed25519-public\n%%%\n", "k.pub"));

        assertTrue(e.getMessage().startsWith("k.pub: line 2 is not base64: "), e.getMessage());
    }

    @Test
    void twoDataLines_areRefused() {
        String text = KeyFiles.publicKeyText(team.authority.verificationKey(), "") + "AAAA\n";

        KeyFileException e = assertThrows(KeyFileException.class, () -> KeyFiles.parsePublicKey(text, "k.pub"));

        assertEquals("k.pub: line 3 is more data after line 2; an Ed25519 public key file has one base64 line", e.getMessage());
    }

    @Test
    void privateKeyWithAForeignPublicHalf_isRefused() {
        SigningKey other = SigningKey.generate(team.random);
        String mine = KeyFiles.privateKeyText(team.authority, "");
        String theirs = KeyFiles.privateKeyText(other, "");
        byte[] a = java.util.Base64.getDecoder().decode(mine.lines().toList().get(1));
        byte[] b = java.util.Base64.getDecoder().decode(theirs.lines().toList().get(1));
        System.arraycopy(b, 32, a, 32, 32);
        String mixed = "smc-key v1 ed25519-private\n" + java.util.Base64.getEncoder().encodeToString(a) + "\n";

        KeyFileException e = assertThrows(KeyFileException.class, () -> KeyFiles.parsePrivateKey(mixed, "mixed.key"));

        assertEquals("mixed.key: the public key " + other.verificationKey().id()
                + " is not the pair of the private key it came with", e.getMessage());
    }

    @Test
    void corruptCredential_isRefused_namingTheFileAndTheField() {
        SigningIdentity id = team.identity("uav-1");
        byte[] encoded = id.credential().encode();
        encoded[0] = 9;
        String text = "smc-credential v1\n" + java.util.Base64.getEncoder().encodeToString(encoded) + "\n";

        KeyFileException e = assertThrows(KeyFileException.class, () -> KeyFiles.parseCredential(text, "uav-1.cred"));

        assertEquals("uav-1.cred: credential: version at byte 0: 9 is not a known version; this reader knows 1", e.getMessage());
    }

    @Test
    void oversizeFile_isRefusedBeforeReading() throws Exception {
        Path big = Files.writeString(dir.resolve("big.key"), "x".repeat(KeyFiles.MAX_FILE_BYTES + 1));

        KeyFileException e = assertThrows(KeyFileException.class, () -> KeyFiles.readPrivateKey(big));

        assertEquals(big + ": 4097 bytes; a key or credential file is at most 4096", e.getMessage());
    }

    @Test
    void crlfLineEnds_areAccepted() throws Exception {
        String text = KeyFiles.publicKeyText(team.authority.verificationKey(), "x").replace("\n", "\r\n");

        assertEquals(team.authority.verificationKey(), KeyFiles.parsePublicKey(text, "k.pub"));
    }
}
