package net.smc.policy.runtime;

import net.smc.policy.api.OpContext;
import net.smc.policy.api.PonderError;
import net.smc.policy.lang.SourcePos;

/**
 * What an operation learns about the call that invoked it, when its Java method declares a
 * leading {@code CallContext} parameter: the cell, the sender, the receiver's handle, and a way to
 * call blocks and raise events within the same run.
 */
public final class CallContext implements OpContext {
    private final Interpreter interpreter;
    private final Execution execution;
    private final Object receiver;
    private final SourcePos pos;

    CallContext(Interpreter interpreter, Execution execution, Object receiver, SourcePos pos) {
        this.interpreter = interpreter;
        this.execution = execution;
        this.receiver = receiver;
        this.pos = pos;
    }

    /** Calls a block with the given arguments in this run. */
    public Object call(Block block, Object... args) {
        return interpreter.call(execution, block, args);
    }

    @Override
    public Object callBlock(Object block, Object... args) {
        if (!(block instanceof Block b)) {
            throw new PonderError("not a block: " + Numbers.abbreviate(Values.print(block)));
        }
        return call(b, args);
    }

    /** Sends a message in this run, as a PonderTalk statement would. */
    @Override
    public Object send(Object receiverObject, String selector, Object... args) {
        return interpreter.send(execution, receiverObject, selector, args, pos);
    }

    public CellRuntime runtime() {
        return interpreter.runtime();
    }

    /** The sender: root for top-level statements, the policy for statements inside a policy. */
    @Override
    public Object subject() {
        return execution.source;
    }

    /** The receiver as PonderTalk sees it (the managed-object handle, not its Java implementation). */
    @Override
    public Object receiver() {
        return receiver;
    }

    /** Where the send is in the source. */
    public SourcePos pos() {
        return pos;
    }

    public Execution execution() {
        return execution;
    }
}
