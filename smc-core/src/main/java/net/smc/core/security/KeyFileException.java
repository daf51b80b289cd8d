package net.smc.core.security;

/**
 * A key or credential file that cannot be used: wrong header, not base64, wrong length, a private
 * key whose public half does not match. The message names the file, the line where it matters, and
 * what was expected.
 */
public final class KeyFileException extends Exception {
    private static final long serialVersionUID = 1L;

    KeyFileException(String message) {
        super(message);
    }
}
