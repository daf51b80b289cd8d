package net.smc.policy.lang;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * A checked unit: its name, its syntax errors (which stop it from running), and what it needs to
 * give its statements again, in order, to be run: its text and the files its includes gave. It
 * does not hold its syntax tree, so a large unit costs its text, not a tree many times larger; its
 * statements are parsed again, one at a time, by {@link #forEachStatement}. Immutable. (A small unit
 * that cells of one process share can keep its tree instead: {@link ParsedUnits}.)
 */
public final class Unit {
    private final String source;
    private final String text;
    private final IncludeResolver includes;
    private final List<SyntaxError> errors;
    /** The statements, for a unit kept parsed by {@link ParsedUnits}; null when they are parsed from the text. */
    private final List<Node> tree;

    Unit(String source, String text, IncludeResolver includes, List<SyntaxError> errors) {
        this.source = source;
        this.text = text;
        this.includes = includes;
        this.errors = List.copyOf(errors);
        this.tree = null;
    }

    /** A unit without errors that keeps its statements' trees ({@link ParsedUnits}). */
    Unit(String source, List<Node> statements) {
        this.source = source;
        this.text = null;
        this.includes = IncludeResolver.NONE;
        this.errors = List.of();
        this.tree = List.copyOf(statements);
    }

    /** A unit refused before it was parsed (too long, say): {@code error} is its only error, it has no statements. */
    public static Unit refused(String source, SyntaxError error) {
        return new Unit(source, "", IncludeResolver.NONE, List.of(error));
    }

    public String source() {
        return source;
    }

    public List<SyntaxError> errors() {
        return errors;
    }

    public boolean hasErrors() {
        return !errors.isEmpty();
    }

    /**
     * Gives each top-level statement, included files' in their place, to {@code action} as soon as
     * it is parsed, so the statements before it may already have run and been dropped. An exception
     * {@code action} throws ends the walk and passes through.
     */
    public void forEachStatement(Consumer<Node> action) {
        if (tree != null) {
            tree.forEach(action);
            return;
        }
        Parser.parse(source, text, includes, action);
    }

    /** The statements that parsed (for a unit with errors: those the parser recovered), as one list. */
    public List<Node> statements() {
        List<Node> all = new ArrayList<>();
        forEachStatement(all::add);
        return List.copyOf(all);
    }
}
