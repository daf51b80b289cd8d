package net.smc.core.security;

/**
 * Bytes that are not a credential of a known version: truncated, a length over its limit, text
 * that is not UTF-8. The message names the field, its byte offset and the rule.
 */
public final class CredentialFormatException extends Exception {
    private static final long serialVersionUID = 1L;

    CredentialFormatException(String message) {
        super(message);
    }
}
