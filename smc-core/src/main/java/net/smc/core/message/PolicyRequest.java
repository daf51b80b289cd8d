package net.smc.core.message;

/** Asks the repository holder for the text of one version of a policy. Answered by a {@link PolicyReply}. */
public record PolicyRequest(String uri, int version) implements Message {
    public PolicyRequest {
        Fields.uri("PolicyRequest.uri", uri);
        Fields.nonNegative("PolicyRequest.version", version);
    }

    @Override
    public MessageType type() {
        return MessageType.POLICY_REQUEST;
    }
}
