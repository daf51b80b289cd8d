package net.smc.policy.stdlib;

import net.smc.policy.runtime.CallContext;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.api.PonderError;
import net.smc.policy.runtime.Values;

/**
 * Ponder2's {@code PonderTalk} object, within one cell: {@code execute:} runs PonderTalk text as a
 * unit of its own (fresh variables, the sender as source) and answers its last statement's value;
 * an error in it (syntax or run time) is the error {@code Caught P2 Exception: <message>} at the
 * {@code execute:} send. {@code create: name} gives the object a name, which {@code test:} needs:
 * in Ponder2 {@code test:} sends the text to that name over RMI; here it runs it in this cell and
 * answers the value's printed form. {@code trace: true} prints each text before running it.
 */
@Managed("PonderTalk")
final class PonderTalkEvaluator {
    private final String name;
    private boolean trace;

    @Op("create")
    PonderTalkEvaluator() {
        this.name = null;
    }

    @Op("create:")
    PonderTalkEvaluator(String name) {
        this.name = name;
    }

    @Op("trace:")
    void trace(boolean on) {
        trace = on;
    }

    @Op("execute:")
    Object execute(CallContext ctx, String text) {
        if (trace) {
            ctx.send(ctx.runtime().root(), "print:", "PonderTalk executing: \n-------------------\n" + text
                    + "\n-------------------");
        }
        try {
            return ctx.runtime().evaluate(ctx.execution(), "PonderTalk", text);
        } catch (PonderError e) {
            throw new PonderError("Caught P2 Exception: " + e.getMessage());
        }
    }

    @Op("test:")
    String test(CallContext ctx, String text) {
        if (name == null) {
            throw new PonderError("PonderTalk has not been given a name (create: it with one)");
        }
        return Values.print(execute(ctx, text));
    }
}
