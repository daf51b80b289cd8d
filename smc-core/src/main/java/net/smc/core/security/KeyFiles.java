package net.smc.core.security;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
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
 * <p>A private key file carries its public half because the JDK cannot derive it from the seed; the
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

    private KeyFiles() {
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
        return Files.readString(path, StandardCharsets.UTF_8);
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
            if (line.isEmpty() || line.startsWith("#")) {
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
