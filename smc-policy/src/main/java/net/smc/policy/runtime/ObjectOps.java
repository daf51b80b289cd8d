package net.smc.policy.runtime;

import net.smc.policy.api.Op;
/** The operations every object (but nil) answers. */
final class ObjectOps {
    private ObjectOps() {
    }

    @Op("class")
    static String className(Object self) {
        return Values.className(self);
    }

    @Op("self")
    static Object self(Object self) {
        return self;
    }

    @Op("==")
    static boolean same(Object self, Object other) {
        return Values.same(self, other);
    }

    @Op("!=")
    static boolean notSame(Object self, Object other) {
        return !Values.same(self, other);
    }
}
