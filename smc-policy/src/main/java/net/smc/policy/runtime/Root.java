package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.lang.IncludeResolver;

/**
 * The root domain of a cell ({@code root}): a domain that also prints, runs other units, loads
 * registered classes and exits.
 */
@Managed("SelfManagedCell")
public final class Root extends Domain {

    Root(CellRuntime runtime) {
        super(runtime);
    }

    /** Prints the argument's printed form as one line on the cell's output; answers the argument. */
    @Op("print:")
    public Object print(Object value) {
        runtime().print(Values.print(value));
        return value;
    }

    /** Runs the text as a unit with fresh variables; answers its last statement's value. */
    @Op("readString:")
    public Object readString(CallContext ctx, String text) {
        return runtime().runNested(ctx.execution(), "readString", text, null);
    }

    /** Runs a file (relative to the reading file's folder, then the repository) or a policy URI. */
    @Op("read:")
    public Object read(CallContext ctx, String name) {
        IncludeResolver.Included file;
        try {
            file = runtime().readFile(name, ctx.pos() == null ? null : ctx.pos().source());
        } catch (java.io.UncheckedIOException e) {
            throw new PonderError("cannot read '" + name + "': " + e.getCause().getMessage());
        }
        if (file == null) {
            throw new PonderError("cannot read '" + name + "': file not found");
        }
        return runtime().runNested(ctx.execution(), file.source(), file.text(), null);
    }

    /** The factory of a registered managed-object class. */
    @Op("load:")
    public ManagedObject load(String name) {
        return runtime().load(name);
    }

    @Op("exit")
    public Object exit() {
        throw new ExitRequest(0);
    }

    @Op("exit:")
    public Object exit(int status) {
        if (status < 0 || status > 255) {
            throw new PonderError("exit status must be between 0 and 255, got " + status);
        }
        throw new ExitRequest(status);
    }

    /** Reports a diagnostic through the cell's reporter. */
    void report(Diagnostic d) {
        runtime().report(d);
    }
}
