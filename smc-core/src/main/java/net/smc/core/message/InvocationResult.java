package net.smc.core.message;

/**
 * The outcome of an {@link Invocation}: either {@code ok} with a PonderTalk value (possibly nil)
 * and no error, or not ok with an error text of 1 to 255 bytes and a nil value.
 */
public record InvocationResult(long inReplyTo, boolean ok, Object value, String error) implements Message {
    public InvocationResult {
        if (ok) {
            value = ValueLimits.value("InvocationResult.value", value);
            if (error != null) {
                throw new IllegalArgumentException("InvocationResult.error is " + Fields.show(error)
                        + " but ok is true; a successful result has a null error");
            }
        } else {
            if (value != null) {
                throw new IllegalArgumentException("InvocationResult.value is " + value
                        + " but ok is false; a failed result has a null value");
            }
            Fields.string("InvocationResult.error", error, 1, WireFormat.MAX_TEXT, "the error of a failed result");
        }
    }

    /** A successful result. */
    public static InvocationResult ok(long inReplyTo, Object value) {
        return new InvocationResult(inReplyTo, true, value, null);
    }

    /** A failed result. */
    public static InvocationResult failed(long inReplyTo, String error) {
        return new InvocationResult(inReplyTo, false, null, error);
    }

    @Override
    public MessageType type() {
        return MessageType.INVOCATION_RESULT;
    }
}
