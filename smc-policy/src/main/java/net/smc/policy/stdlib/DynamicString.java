package net.smc.policy.stdlib;

import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.api.PonderError;
import net.smc.policy.runtime.Values;

/**
 * A string that can change, shared by reference (so a block can build one up, unlike a string
 * variable, which a block only copies): {@code create}, {@code create: "text"}, {@code add: x}
 * (appends x's printed form; answers the receiver), {@code set: x}, {@code clear},
 * {@code asString}, {@code size}.
 */
@Managed("DynamicString")
final class DynamicString {
    /** Longest text, in characters, as for strings built with {@code +}. */
    static final int MAX_LENGTH = 64 * 1024 * 1024;
    private final StringBuilder text = new StringBuilder();

    @Op("create")
    DynamicString() {
    }

    @Op("create:")
    DynamicString(Object initial) {
        add(initial);
    }

    @Op("add:")
    void add(Object value) {
        String tail = Values.print(value);
        if ((long) text.length() + tail.length() > MAX_LENGTH) {
            throw new PonderError("string longer than " + MAX_LENGTH + " characters");
        }
        text.append(tail);
    }

    @Op("set:")
    void set(Object value) {
        text.setLength(0);
        add(value);
    }

    @Op("clear")
    void clear() {
        text.setLength(0);
    }

    @Op("asString")
    String asString() {
        return text.toString();
    }

    @Op("size")
    int size() {
        return text.length();
    }
}
