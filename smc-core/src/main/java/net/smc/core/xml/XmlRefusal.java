package net.smc.core.xml;

/**
 * A document an {@link XmlReader} does not accept: not well-formed, with a DOCTYPE, or beyond its
 * {@link XmlLimits}. The message names the rule; the position is apart, so that callers can prefix
 * it in their own format ({@code FILE:LINE:COL: message}).
 */
public final class XmlRefusal extends Exception {
    private static final long serialVersionUID = 1L;

    private final int line;
    private final int column;

    XmlRefusal(int line, int column, String message) {
        super(message, null, false, false);
        this.line = Math.max(line, 1);
        this.column = Math.max(column, 1);
    }

    /** The line of what was refused, from 1. */
    public int line() {
        return line;
    }

    /** The column of what was refused, from 1. */
    public int column() {
        return column;
    }
}
