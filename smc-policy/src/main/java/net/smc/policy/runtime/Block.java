package net.smc.policy.runtime;

import net.smc.policy.api.Nil;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import java.util.List;
import java.util.Map;
import net.smc.policy.lang.SourcePos;

/**
 * A block: code with the values, frozen when it was created, of the variables its code reads
 * (smc-policy/PONDERTALK.md section 4). A block made by {@code onError:} runs another block and, on error,
 * its handler.
 */
@Managed("Block")
public final class Block {
    final Interpreter.BlockCode code;
    final Object[] captured;
    /** Every variable seen where the block was made, when its code reads {@code Variables}; else empty. */
    final Map<String, Object> scope;
    final Block guarded;
    final Block handler;

    Block(Interpreter.BlockCode code, Object[] captured, Map<String, Object> scope) {
        this.code = code;
        this.captured = captured;
        this.scope = scope;
        this.guarded = null;
        this.handler = null;
    }

    private Block(Block guarded, Block handler) {
        this.code = guarded.code;
        this.captured = guarded.captured;
        this.scope = guarded.scope;
        this.guarded = guarded;
        this.handler = handler;
    }

    /** The parameter names, in order. */
    public List<String> params() {
        return List.of(code.params);
    }

    /** Where the block's {@code [} is. */
    public SourcePos pos() {
        return code.pos;
    }

    @Op("value")
    public Object value(CallContext ctx) {
        return ctx.call(this);
    }

    @Op("value:")
    public Object value(CallContext ctx, Object a) {
        return ctx.call(this, a);
    }

    @Op("value:value:")
    public Object value(CallContext ctx, Object a, Object b) {
        return ctx.call(this, a, b);
    }

    @Op("value:value:value:")
    public Object value(CallContext ctx, Object a, Object b, Object c) {
        return ctx.call(this, a, b, c);
    }

    @Op("values:")
    public Object values(CallContext ctx, PArray args) {
        return ctx.call(this, args.items().toArray());
    }

    /** Binds the parameters by name from a hash. */
    @Op("valueHash:")
    public Object valueHash(CallContext ctx, PHash args) {
        Object[] bound = new Object[code.params.length];
        for (int i = 0; i < bound.length; i++) {
            bound[i] = args.at(code.params[i]);
        }
        return ctx.call(this, bound);
    }

    @Op("whileTrue:")
    public Object whileTrue(CallContext ctx, Block body) {
        while (ctx.call(this) == Boolean.TRUE) {
            ctx.call(body);
        }
        return Nil.NIL;
    }

    @Op("whileFalse:")
    public Object whileFalse(CallContext ctx, Block body) {
        while (ctx.call(this) == Boolean.FALSE) {
            ctx.call(body);
        }
        return Nil.NIL;
    }

    @Op("onError:")
    public Block onError(Block errorHandler) {
        return new Block(this, errorHandler);
    }

    @Override
    public String toString() {
        return "<block " + code.pos + ">";
    }
}
