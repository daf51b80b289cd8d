package net.smc.core.message;

/**
 * A policy named by a role assignment: its repository URI (e.g. {@code policy:/roles/relay}) and
 * version. The assignee fetches the text with a {@link PolicyRequest} unless it holds that version.
 */
public record PolicyRef(String uri, int version) {
    public PolicyRef {
        Fields.uri("PolicyRef.uri", uri);
        Fields.nonNegative("PolicyRef.version", version);
    }
}
