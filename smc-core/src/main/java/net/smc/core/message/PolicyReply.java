package net.smc.core.message;

/**
 * The PonderTalk text of one version of a policy, up to {@link WireFormat#MAX_POLICY_TEXT} UTF-8
 * bytes. On the wire the codec deflates it when that is shorter (see the wire-format note, "policy
 * text"); the record always holds the text itself. Longer than one datagram, it travels in fragments.
 */
public record PolicyReply(long inReplyTo, String uri, int version, String text) implements Message {
    public PolicyReply {
        Fields.uri("PolicyReply.uri", uri);
        Fields.nonNegative("PolicyReply.version", version);
        Fields.string("PolicyReply.text", text, 0, WireFormat.MAX_POLICY_TEXT, "a policy text");
    }

    @Override
    public MessageType type() {
        return MessageType.POLICY_REPLY;
    }
}
