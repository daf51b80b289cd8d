package net.smc.policy.runtime;

import net.smc.policy.api.Nil;
import net.smc.policy.api.Op;
/** Operations of booleans. */
final class BooleanOps {
    private BooleanOps() {
    }

    @Op("not")
    static boolean not(Boolean self) {
        return !self;
    }

    @Op("&")
    static boolean and(Boolean self, boolean other) {
        return self && other;
    }

    @Op("|")
    static boolean or(Boolean self, boolean other) {
        return self || other;
    }

    @Op("and:")
    static Object andBlock(CallContext ctx, Boolean self, Block other) {
        return self ? ctx.call(other) : Boolean.FALSE;
    }

    @Op("or:")
    static Object orBlock(CallContext ctx, Boolean self, Block other) {
        return self ? Boolean.TRUE : ctx.call(other);
    }

    @Op("ifTrue:")
    static Object ifTrue(CallContext ctx, Boolean self, Block then) {
        return self ? ctx.call(then) : Nil.NIL;
    }

    @Op("ifFalse:")
    static Object ifFalse(CallContext ctx, Boolean self, Block otherwise) {
        return self ? Nil.NIL : ctx.call(otherwise);
    }

    @Op("ifTrue:ifFalse:")
    static Object ifTrueIfFalse(CallContext ctx, Boolean self, Block then, Block otherwise) {
        return ctx.call(self ? then : otherwise);
    }

    @Op("ifFalse:ifTrue:")
    static Object ifFalseIfTrue(CallContext ctx, Boolean self, Block otherwise, Block then) {
        return ctx.call(self ? then : otherwise);
    }
}
