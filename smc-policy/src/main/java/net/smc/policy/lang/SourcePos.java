package net.smc.policy.lang;

/**
 * A place in PonderTalk source text: the unit's name (usually a file name), a line and a column,
 * both counted from 1.
 */
public record SourcePos(String source, int line, int column) {

    /** Formats the position as {@code source:line:column}, the prefix of every diagnostic. */
    @Override
    public String toString() {
        return source + ":" + line + ":" + column;
    }
}
