package net.smc.policy.lang;

/** A compile-time error: where it is and what rule was broken. Immutable. */
public record SyntaxError(SourcePos pos, String message) {

    @Override
    public String toString() {
        return pos + ": " + message;
    }
}
