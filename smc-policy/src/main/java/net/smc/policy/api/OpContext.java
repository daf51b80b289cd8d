package net.smc.policy.api;

/**
 * What an operation learns about the call that invoked it, when its Java method declares a leading
 * {@code OpContext} parameter: the sender, the receiver's handle, and a way to send messages and
 * call blocks within the same run (so that limits, authorisation and error positions apply).
 */
public interface OpContext {

    /** The sender: root for top-level statements, the policy for statements inside a policy. */
    Object subject();

    /** The receiver as PonderTalk sees it (the managed-object handle, not its Java implementation). */
    Object receiver();

    /** Sends a message in this run, as a PonderTalk statement would. */
    Object send(Object receiver, String selector, Object... args);

    /**
     * Calls a block (a PonderTalk value passed to the operation) with the given arguments in this run.
     *
     * @throws PonderError when {@code block} is not a block
     */
    Object callBlock(Object block, Object... args);
}
