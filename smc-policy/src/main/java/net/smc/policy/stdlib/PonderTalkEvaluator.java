package net.smc.policy.stdlib;

import net.smc.policy.runtime.CallContext;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.api.PonderError;
import net.smc.policy.api.TeamAddress;
import java.math.BigDecimal;
import net.smc.policy.runtime.Values;

/**
 * Ponder2's {@code PonderTalk} object, within one cell: {@code execute:} runs PonderTalk text as a
 * unit of its own (fresh variables, the sender as source) and answers its last statement's value;
 * an error in it (syntax or run time) is the error {@code Caught P2 Exception: <message>} at the
 * {@code execute:} send. {@code create: name} gives the object a name, which {@code test:} needs:
 * in Ponder2 {@code test:} sends the text to that name over RMI; here it runs it in this cell and
 * answers the value's printed form. {@code trace: true} prints each text before running it.
 *
 * <p>Named with a team address, {@code create: "/team/<cell>"}, it stands for that other cell of
 * the team: {@code execute:} and {@code test:} send the text there over the cell's
 * {@link net.smc.policy.api.TeamLink} and answer at once with a call number; the value (for
 * {@code test:} its printed form) or the error arrives later as the event {@code remoteResult}.
 * The receiving cell evaluates it only if its authorisation policies allow the action
 * {@code evaluate:} (denied by default).
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
        if (TeamAddress.isTeamAddress(name) && !TeamAddress.parse(name).path().isEmpty()) {
            throw new PonderError("a remote PonderTalk is named by its cell alone, as \"/team/<cell>\"; got '" + name + "'");
        }
        this.name = name;
    }

    /** The other cell this object stands for, or null when it evaluates here. */
    private String remoteCell() {
        return TeamAddress.isTeamAddress(name) ? TeamAddress.parse(name).cell() : null;
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
        String cell = remoteCell();
        if (cell != null) {
            return BigDecimal.valueOf(ctx.runtime().teamLink().evaluate(cell, text, false));
        }
        try {
            return ctx.runtime().evaluate(ctx.execution(), "PonderTalk", text);
        } catch (PonderError e) {
            throw new PonderError("Caught P2 Exception: " + e.getMessage());
        }
    }

    @Op("test:")
    Object test(CallContext ctx, String text) {
        if (name == null) {
            throw new PonderError("PonderTalk has not been given a name (create: it with one)");
        }
        String cell = remoteCell();
        if (cell != null) {
            return BigDecimal.valueOf(ctx.runtime().teamLink().evaluate(cell, text, true));
        }
        return Values.print(execute(ctx, text));
    }
}
