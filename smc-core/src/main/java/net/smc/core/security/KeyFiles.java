package net.smc.core.security;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Base64;
import java.util.List;

/**
 * The text files keys and credentials live in between missions: small, versioned, readable in a
 * terminal, and safe to mix up (each says what it holds, so a public key given where a private one
 * is wanted is refused by name, not misread). Every file is:
 *
 * <pre>
 * HEADER                    exactly one of the three below, the first line
 * # comment                 any number of comment or blank lines, ignored
 * BASE64                    one line, standard base64 with padding
 * </pre>
 *
 * <table>
 *   <caption>Kinds of file</caption>
 *   <tr><th>header</th><th>base64 of</th></tr>
 *   <tr><td>{@code smc-key v1 ed25519-private}</td><td>32-byte seed, then the 32-byte public key (64 bytes)</td></tr>
 *   <tr><td>{@code smc-key v1 ed25519-public}</td><td>the 32-byte public key</td></tr>
 *   <tr><td>{@code smc-credential v1}</td><td>a credential in its binary form (see {@link Credential})</td></tr>
 * </table>
 *
 * <p>A private key file says what it is for on a line {@code use: authority} or {@code use: vehicle}
 * after its header (files written before that line existed are recognised by the comment
 * {@code smc keys} wrote: {@code # mission authority} or {@code # vehicle ID}), and is read only when
 * its owner alone may read it (no group or other permission bits, where the file system has POSIX
 * permissions). A private key file carries its public half because the JDK cannot derive it from the seed; the
 * two are checked to match on reading. Files are at most {@value #MAX_FILE_BYTES} bytes.
 */
public final class KeyFiles {
    /** The most bytes a key or credential file may have. */
    public static final int MAX_FILE_BYTES = 4096;

    /** What a file holds, by its header line. */
    public enum Kind {
        PRIVATE_KEY("smc-key v1 ed25519-private", "an Ed25519 private key"),
        PUBLIC_KEY("smc-key v1 ed25519-public", "an Ed25519 public key"),
        CREDENTIAL("smc-credential v1", "a credential");

        private final String header;
        private final String description;

        Kind(String header, String description) {
            this.header = header;
            this.description = description;
        }

        /** The first line of a file of this kind. */
        public String header() {
            return header;
        }

        /** What such a file holds, in words. */
        public String description() {
            return description;
        }
    }

    /** What a private key is for. */
    public enum Use {
        /** A mission authority's key: it signs credentials. */
        AUTHORITY("authority", "mission authority"),
        /** A vehicle's key: it signs the vehicle's traffic. */
        VEHICLE("vehicle", "vehicle ");

        private final String word;
        private final String legacyComment;

        Use(String word, String legacyComment) {
            this.word = word;
            this.legacyComment = legacyComment;
        }

        /** The word of its {@code use:} line. */
        public String word() {
            return word;
        }
    }

    private static final String USE_PREFIX = "use:";

    private KeyFiles() {
    }

    /** The text of a private key file for {@code use}; {@code comment} says whose key it is. */
    public static String privateKeyText(SigningKey key, Use use, String comment) {
        String text = privateKeyText(key, comment);
        int afterHeader = text.indexOf('\n') + 1;
        return text.substring(0, afterHeader) + USE_PREFIX + " " + use.word + "\n" + text.substring(afterHeader);
    }

    /**
     * What a private key file's key is for: its {@code use:} line, or for a file written before that
     * line existed, the comment {@code smc keys} wrote.
     *
     * @throws KeyFileException when the file does not say, or says something else
     */
    public static Use useOf(String text, String source) throws KeyFileException {
        List<String> lines = lines(text);
        for (int i = 1; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            if (line.startsWith(USE_PREFIX)) {
                String word = line.substring(USE_PREFIX.length()).strip();
                for (Use use : Use.values()) {
                    if (use.word.equals(word)) {
                        return use;
                    }
                }
                throw new KeyFileException(source + ": line " + (i + 1) + " is '" + shorten(line)
                        + "'; a private key's use is 'use: authority' or 'use: vehicle'");
            }
        }
        for (int i = 1; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            for (Use use : Use.values()) {
                if (line.startsWith("#") && line.substring(1).strip().startsWith(use.legacyComment)) {
                    return use;
                }
            }
        }
        throw new KeyFileException(source + ": the private key does not say whether it is an authority's or a vehicle's "
                + "(no 'use:' line); write a new one with 'smc keys authority' or 'smc keys vehicle'");
    }

    /**
     * Refuses a private key file that others than its owner may read or write, where the file system
     * has POSIX permissions.
     *
     * @throws KeyFileException naming the mode and the {@code chmod} that fixes it
     */
    public static void checkPrivate(Path path) throws IOException, KeyFileException {
        java.util.Set<java.nio.file.attribute.PosixFilePermission> permissions;
        try {
            permissions = Files.getPosixFilePermissions(path);
        } catch (UnsupportedOperationException e) {
            return;   // no POSIX permissions to check on this file system
        }
        java.util.Set<java.nio.file.attribute.PosixFilePermission> open = java.util.EnumSet.copyOf(permissions);
        open.removeAll(java.util.EnumSet.of(java.nio.file.attribute.PosixFilePermission.OWNER_READ,
                java.nio.file.attribute.PosixFilePermission.OWNER_WRITE,
                java.nio.file.attribute.PosixFilePermission.OWNER_EXECUTE));
        if (!open.isEmpty()) {
            throw new KeyFileException(path + ": private key file has mode " + mode(permissions)
                    + " (" + java.nio.file.attribute.PosixFilePermissions.toString(permissions)
                    + "), so others than its owner may read it; a private key must be readable by its owner only: "
                    + "chmod 600 " + path);
        }
    }

    private static String mode(java.util.Set<java.nio.file.attribute.PosixFilePermission> permissions) {
        int mode = 0;
        for (java.nio.file.attribute.PosixFilePermission p : permissions) {
            mode |= 1 << (8 - p.ordinal());
        }
        return String.format("%03o", mode);
    }

    /**
     * The private key at {@code path}, checked to be for {@code use} and readable by its owner only.
     *
     * @throws KeyFileException when it is not, naming what is wrong and how to fix it
     */
    public static SigningKey readPrivateKey(Path path, Use use) throws IOException, KeyFileException {
        String text = read(path);
        SigningKey key = parsePrivateKey(text, path.toString());
        checkPrivate(path);
        Use actual = useOf(text, path.toString());
        if (actual != use) {
            throw new KeyFileException(path + ": this is a " + actual.word + "'s private key, not a" 
                    + (use == Use.AUTHORITY ? "n " : " ") + use.word + "'s; give the "
                    + (use == Use.AUTHORITY ? "authority key written by 'smc keys authority' (authority.key)"
                    : "vehicle key written by 'smc keys vehicle' (ID.key)"));
        }
        return key;
    }

    /** The text of a private key file; {@code comment} (one line, may be empty) says whose key it is. */
    public static String privateKeyText(SigningKey key, String comment) {
        byte[] both = PairKeys.concat(key.seed(), key.verificationKey().bytes());
        return text(Kind.PRIVATE_KEY, comment, both);
    }

    public static String publicKeyText(VerificationKey key, String comment) {
        return text(Kind.PUBLIC_KEY, comment, key.bytes());
    }

    public static String credentialText(Credential credential, String comment) {
        return text(Kind.CREDENTIAL, comment, credential.encode());
    }

    /**
     * What the text holds, by its first line.
     *
     * @param source names the text in errors (its file name)
     * @throws KeyFileException when the first line is no known header
     */
    public static Kind kindOf(String text, String source) throws KeyFileException {
        String first = lines(text).get(0);
        for (Kind kind : Kind.values()) {
            if (kind.header.equals(first)) {
                return kind;
            }
        }
        throw new KeyFileException(source + ": line 1 is '" + shorten(first) + "'; expected a key or credential header: "
                + Arrays.stream(Kind.values()).map(k -> "'" + k.header + "'").reduce((a, b) -> a + ", " + b).orElse(""));
    }

    public static SigningKey parsePrivateKey(String text, String source) throws KeyFileException {
        byte[] both = payload(text, source, Kind.PRIVATE_KEY, 2 * VerificationKey.BYTES);
        try {
            return SigningKey.of(Arrays.copyOf(both, SigningKey.SEED_BYTES),
                    VerificationKey.of(Arrays.copyOfRange(both, SigningKey.SEED_BYTES, both.length)));
        } catch (IllegalArgumentException e) {
            throw new KeyFileException(source + ": " + e.getMessage());
        }
    }

    public static VerificationKey parsePublicKey(String text, String source) throws KeyFileException {
        try {
            return VerificationKey.of(payload(text, source, Kind.PUBLIC_KEY, VerificationKey.BYTES));
        } catch (IllegalArgumentException e) {
            throw new KeyFileException(source + ": " + e.getMessage());
        }
    }

    public static Credential parseCredential(String text, String source) throws KeyFileException {
        byte[] bytes = payload(text, source, Kind.CREDENTIAL, -1);
        try {
            return Credential.decode(bytes);
        } catch (CredentialFormatException e) {
            throw new KeyFileException(source + ": " + e.getMessage());
        }
    }

    /**
     * The text of the file at {@code path}.
     *
     * @throws KeyFileException when it is larger than {@value #MAX_FILE_BYTES} bytes
     */
    public static String read(Path path) throws IOException, KeyFileException {
        long size = Files.size(path);
        if (size > MAX_FILE_BYTES) {
            throw new KeyFileException(path + ": " + size + " bytes; a key or credential file is at most " + MAX_FILE_BYTES);
        }
        return net.smc.policy.lang.SourceFiles.decode(Files.readAllBytes(path));
    }

    public static SigningKey readPrivateKey(Path path) throws IOException, KeyFileException {
        return parsePrivateKey(read(path), path.toString());
    }

    public static VerificationKey readPublicKey(Path path) throws IOException, KeyFileException {
        return parsePublicKey(read(path), path.toString());
    }

    public static Credential readCredential(Path path) throws IOException, KeyFileException {
        return parseCredential(read(path), path.toString());
    }

    private static String text(Kind kind, String comment, byte[] payload) {
        StringBuilder out = new StringBuilder(kind.header).append('\n');
        if (comment != null && !comment.isBlank()) {
            out.append("# ").append(comment.replaceAll("[\\r\\n]+", " ")).append('\n');
        }
        return out.append(Base64.getEncoder().encodeToString(payload)).append('\n').toString();
    }

    /** The decoded base64 line of a file of {@code kind}; exactly {@code length} bytes unless it is -1. */
    private static byte[] payload(String text, String source, Kind kind, int length) throws KeyFileException {
        List<String> lines = lines(text);
        if (!kind.header.equals(lines.get(0))) {
            String other = Arrays.stream(Kind.values()).filter(k -> k.header.equals(lines.get(0)))
                    .map(k -> " (that is the header of " + k.description + " file)").findFirst().orElse("");
            throw new KeyFileException(source + ": line 1 is '" + shorten(lines.get(0)) + "'" + other + "; expected '"
                    + kind.header + "', the header of " + kind.description + " file");
        }
        String data = null;
        int dataLine = 0;
        for (int i = 1; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            if (line.isEmpty() || line.startsWith("#") || (kind == Kind.PRIVATE_KEY && line.startsWith(USE_PREFIX))) {
                continue;
            }
            if (data != null) {
                throw new KeyFileException(source + ": line " + (i + 1) + " is more data after line " + dataLine
                        + "; " + kind.description + " file has one base64 line");
            }
            data = line;
            dataLine = i + 1;
        }
        if (data == null) {
            throw new KeyFileException(source + ": no base64 line after the header; " + kind.description + " file has one");
        }
        byte[] bytes;
        try {
            bytes = Base64.getDecoder().decode(data);
        } catch (IllegalArgumentException e) {
            throw new KeyFileException(source + ": line " + dataLine + " is not base64: " + e.getMessage());
        }
        if (length >= 0 && bytes.length != length) {
            throw new KeyFileException(source + ": line " + dataLine + " holds " + bytes.length + " bytes; " + kind.description
                    + " file holds " + length);
        }
        return bytes;
    }

    private static List<String> lines(String text) {
        List<String> lines = new ArrayList<>(text.lines().map(l -> l.endsWith("\r") ? l.substring(0, l.length() - 1) : l).toList());
        if (lines.isEmpty()) {
            lines.add("");
        }
        return lines;
    }

    private static String shorten(String line) {
        return line.length() <= 60 ? line : line.substring(0, 57) + "...";
    }
}
