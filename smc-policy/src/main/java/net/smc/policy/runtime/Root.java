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
    public Object print(CallContext ctx, Object value) {
        String line = Values.print(value);
        ctx.execution().charge(line.length(), "print:");
        runtime().print(line);
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

    /** The user's arguments ({@code smc run FILE -- a b c}), as given. */
    @Op("argsAsArray")
    public PArray argsAsArray() {
        return new PArray(runtime().arguments());
    }

    /**
     * The user's arguments as a hash, as Ponder2 reads them: an argument starting with '-' is a key
     * (without the '-'); the next argument is its value unless it starts with '-' too (then the
     * value is ""); a value without a key before it is ignored.
     */
    @Op("argsAsHash")
    public PHash argsAsHash() {
        PHash hash = new PHash();
        String key = null;
        for (String arg : runtime().arguments()) {
            if (arg.startsWith("-")) {
                if (key != null) {
                    hash.put(key, "");
                }
                key = arg.substring(1);
            } else if (key != null) {
                hash.put(key, arg);
                key = null;
            }
        }
        if (key != null) {
            hash.put(key, "");
        }
        return hash;
    }

    /** The free memory of the Java VM, in bytes (Ponder2 also prints it and collects garbage; this does neither). */
    @Op("memory")
    public long memory() {
        return Runtime.getRuntime().freeMemory();
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
