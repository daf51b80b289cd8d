package net.smc.policy.lang;

import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Consumer;

/**
 * Parses a PonderTalk unit into {@link Node}s (grammar: smc-policy/PONDERTALK.md section 3). The parser
 * recovers at statement boundaries, so one call reports every syntax error of the unit; it bounds
 * nesting so that no input can exhaust the stack.
 *
 * <p>It reads tokens from the {@link Lexer} as it needs them (one token of lookahead beyond the
 * current one) and hands each top-level statement to a consumer as soon as it is parsed, so parsing
 * holds neither a unit's tokens nor its tree: memory stays within the source text and one statement.
 */
public final class Parser {
    /** Deepest nesting of parentheses, blocks, arrays and assignments accepted. */
    public static final int MAX_NESTING = 256;
    /** Deepest chain of includes accepted. */
    public static final int MAX_INCLUDE_DEPTH = 16;
    /** Errors reported before the parser gives up on a unit. */
    public static final int MAX_ERRORS = 100;
    /** Longest chain of sends one expression may build (each send's receiver is the previous send). */
    public static final int MAX_EXPRESSION_DEPTH = 2000;

    private final Lexer lexer;
    /** This file's lexical errors, in the order of their places; merged with its parse errors by place. */
    private final List<SyntaxError> lexErrors = new ArrayList<>();
    /** This file's parse errors, and the errors of the files it includes, in order. */
    private final List<SyntaxError> errors = new ArrayList<>();
    /** Errors of the unit found before this file was reached (earlier files of an include chain). */
    private final int errorsBefore;
    private final IncludeResolver includes;
    private final int includeDepth;
    private final Consumer<Node> statements;
    private Token current;
    /** The token after {@link #current}, once looked at; {@code null} before. */
    private Token following;
    private int depth;
    /** The brackets the tokens consumed so far opened and did not close, innermost first. */
    private final java.util.ArrayDeque<TokenKind> open = new java.util.ArrayDeque<>();
    /** How deep each send of the current statement is (sends are built left to right, so receivers come first). */
    private final java.util.IdentityHashMap<Node, Integer> sendDepths = new java.util.IdentityHashMap<>();

    private Parser(String source, String text, IncludeResolver includes, int includeDepth, int errorsBefore,
                   Consumer<Node> statements) {
        this.lexer = new Lexer(source, text, lexErrors);
        this.includes = includes;
        this.includeDepth = includeDepth;
        this.errorsBefore = errorsBefore;
        this.statements = statements;
        this.current = lexer.next();
    }

    /** Parses a unit that may not include files. */
    public static Unit parse(String source, String text) {
        return parse(source, text, IncludeResolver.NONE);
    }

    /**
     * Checks a unit; {@code include "file"} statements are resolved with {@code includes} (each
     * file once: the unit remembers what they gave). The unit keeps its text, not its tree: its
     * statements are parsed again when they are asked for.
     */
    public static Unit parse(String source, String text, IncludeResolver includes) {
        IncludeResolver remembered = IncludeResolver.remembering(includes);
        List<SyntaxError> errors = parse(source, text, remembered, statement -> {
        });
        return new Unit(source, text, remembered, errors);
    }

    /**
     * Parses a unit and gives each top-level statement, included files' statements in their place,
     * to {@code statements} as soon as it is parsed; answers the syntax errors (at most
     * {@link #MAX_ERRORS}, then one line that counts them all). An exception that
     * {@code statements} throws ends the parse and passes through.
     */
    public static List<SyntaxError> parse(String source, String text, IncludeResolver includes,
                                          Consumer<Node> statements) {
        List<SyntaxError> errors = parseFile(source, text, includes, 0, 0, statements);
        if (errors.size() > MAX_ERRORS) {
            int all = errors.size();
            List<SyntaxError> shown = new ArrayList<>(errors.subList(0, MAX_ERRORS));
            shown.add(new SyntaxError(errors.get(MAX_ERRORS).pos(),
                    "too many syntax errors (" + all + "); only the first " + MAX_ERRORS + " are listed"));
            errors = shown;
        }
        return errors;
    }

    /**
     * Parses one file of a unit; answers its errors in the order of their places in it (lexical and
     * parse errors merged), an include's errors where the include stands.
     */
    private static List<SyntaxError> parseFile(String source, String text, IncludeResolver includes, int includeDepth,
                                               int errorsBefore, Consumer<Node> statements) {
        Parser parser = new Parser(source, text, includes, includeDepth, errorsBefore, statements);
        parser.unit();
        List<SyntaxError> all = new ArrayList<>();
        java.util.Iterator<SyntaxError> lexical = parser.lexErrors.iterator();
        SyntaxError nextLexical = lexical.hasNext() ? lexical.next() : null;
        for (SyntaxError e : parser.errors) {
            // an include's errors name their own file; they stay where the include is
            boolean own = e.pos().source().equals(source);
            while (own && nextLexical != null && before(nextLexical.pos(), e.pos())) {
                all.add(nextLexical);
                nextLexical = lexical.hasNext() ? lexical.next() : null;
            }
            all.add(e);
        }
        while (nextLexical != null) {
            all.add(nextLexical);
            nextLexical = lexical.hasNext() ? lexical.next() : null;
        }
        return all;
    }

    private static boolean before(SourcePos a, SourcePos b) {
        return a.line() < b.line() || a.line() == b.line() && a.column() <= b.column();
    }

    /** Thrown to abandon the current statement after an error has been recorded. */
    private static final class Abandon extends RuntimeException {
        final boolean wholeUnit;

        Abandon(boolean wholeUnit) {
            super(null, null, false, false);
            this.wholeUnit = wholeUnit;
        }
    }

    /** Errors of the unit so far. */
    private int errorCount() {
        return errorsBefore + lexErrors.size() + errors.size();
    }

    private void unit() {
        while (!check(TokenKind.EOF)) {
            if (errorCount() > MAX_ERRORS) {
                break;
            }
            try {
                sendDepths.clear();
                topStatement();
                if (!check(TokenKind.EOF)) {
                    expect(TokenKind.DOT, "'.' or a message");
                }
            } catch (Abandon abandon) {
                if (abandon.wholeUnit) {
                    break;
                }
                synchronize();
            }
        }
    }

    /** Parses one top-level statement (or include) and hands it on. */
    private void topStatement() {
        Token first = peek();
        if (first.kind() == TokenKind.IDENT && first.text().equals("include")
                && peekNext().kind() == TokenKind.STRING) {
            advance();
            Token name = advance();
            include(name);
            return;
        }
        statements.accept(statement());
    }

    private void include(Token name) {
        String file = (String) name.value();
        if (includeDepth >= MAX_INCLUDE_DEPTH) {
            throw error(name, "include nested deeper than " + MAX_INCLUDE_DEPTH + " levels (does a file include itself?)");
        }
        IncludeResolver.Included included;
        try {
            included = includes.resolve(file, name.pos().source());
        } catch (UncheckedIOException e) {
            throw error(name, "cannot read '" + file + "': " + e.getCause().getMessage());
        }
        if (included == null) {
            throw error(name, "cannot read '" + file + "': file not found");
        }
        errors.addAll(parseFile(included.source(), included.text(), includes, includeDepth + 1, errorCount(),
                statements));
    }

    /**
     * Skips to just after the next '.' that ends a top-level statement, or to the end. A '.' inside
     * a block separates its statements and is skipped. Inside parentheses or an array literal (and
     * no block) no '.' belongs: one there that ends its line ends the statement too (the bracket
     * was left open, and must not swallow the rest of the unit and hide its other errors), while one
     * with more of the line after it is a stray '.' in a statement that goes on, and is skipped.
     */
    private void synchronize() {
        while (!check(TokenKind.EOF)) {
            Token t = advance();
            if (t.kind() != TokenKind.DOT) {
                continue;
            }
            boolean endsLine = check(TokenKind.EOF) || peek().pos().line() > t.pos().line();
            if (open.isEmpty() || !open.contains(TokenKind.LBRACKET) && endsLine) {
                open.clear();
                return;
            }
        }
    }

    private Node statement() {
        enter();
        try {
            Token first = peek();
            if (peekNext().kind() == TokenKind.ASSIGN) {
                if (first.kind() == TokenKind.IDENT) {
                    advance();
                    advance();
                    return new Node.Assign(first.pos(), first.text(), statement());
                }
                if (first.kind() == TokenKind.PATH) {
                    throw error(first, "cannot assign to a path '" + first.text() + "'");
                }
            }
            return expression();
        } finally {
            depth--;
        }
    }

    private Node expression() {
        Node receiver = operand();
        List<Node.Message> chain = messages();
        if (!check(TokenKind.SEMICOLON)) {
            return fold(receiver, chain);
        }
        if (chain.isEmpty()) {
            throw error(peek(), "expected a message before ';', found " + peek().describe());
        }
        Node cascadeReceiver = fold(receiver, chain.subList(0, chain.size() - 1));
        List<List<Node.Message>> chains = new ArrayList<>();
        chains.add(List.of(chain.get(chain.size() - 1)));
        while (match(TokenKind.SEMICOLON)) {
            List<Node.Message> part = messages();
            if (part.isEmpty()) {
                throw error(peek(), "expected a message after ';', found " + peek().describe());
            }
            chains.add(part);
        }
        return new Node.Cascade(chain.get(0).pos(), cascadeReceiver, chains);
    }

    private Node fold(Node receiver, List<Node.Message> chain) {
        Node result = receiver;
        for (Node.Message m : chain) {
            result = send(result, m);
        }
        return result;
    }

    /** Builds a send, refusing chains deeper than {@link #MAX_EXPRESSION_DEPTH}. */
    private Node send(Node receiver, Node.Message message) {
        int deepest = sendDepths.getOrDefault(receiver, 0);
        for (Node arg : message.args()) {
            deepest = Math.max(deepest, sendDepths.getOrDefault(arg, 0));
        }
        if (deepest + 1 > MAX_EXPRESSION_DEPTH) {
            errors.add(new SyntaxError(message.pos(), "expression deeper than " + MAX_EXPRESSION_DEPTH + " sends"));
            throw new Abandon(true);
        }
        Node.Send send = new Node.Send(receiver, message);
        sendDepths.put(send, deepest + 1);
        return send;
    }

    /** {@code unary* binaries? keywords?}, possibly empty. */
    private List<Node.Message> messages() {
        List<Node.Message> chain = new ArrayList<>();
        while (check(TokenKind.IDENT)) {
            Token selector = advance();
            chain.add(new Node.Message(selector.pos(), selector.text(), List.of()));
        }
        while (check(TokenKind.BINOP)) {
            chain.add(binary());
        }
        if (check(TokenKind.KEYWORD)) {
            Token first = peek();
            StringBuilder selector = new StringBuilder();
            List<Node> args = new ArrayList<>();
            while (check(TokenKind.KEYWORD)) {
                selector.append(advance().text());
                Node arg = unaryOperand();
                while (check(TokenKind.BINOP)) {
                    arg = send(arg, binary());
                }
                args.add(arg);
            }
            chain.add(new Node.Message(first.pos(), selector.toString(), args));
        }
        return chain;
    }

    private Node.Message binary() {
        Token op = advance();
        return new Node.Message(op.pos(), op.text(), List.of(unaryOperand()));
    }

    private Node unaryOperand() {
        Node result = operand();
        while (check(TokenKind.IDENT)) {
            Token selector = advance();
            result = send(result, new Node.Message(selector.pos(), selector.text(), List.of()));
        }
        return result;
    }

    private Node operand() {
        Token t = peek();
        switch (t.kind()) {
            case NUMBER, STRING, BOOLEAN -> {
                advance();
                return new Node.Literal(t.pos(), t.value());
            }
            case IDENT -> {
                advance();
                return new Node.Name(t.pos(), t.text(), List.of(t.text()), false);
            }
            case PATH -> {
                advance();
                return path(t);
            }
            case LPAREN -> {
                advance();
                Node inner = statement();
                expect(TokenKind.RPAREN, "')'");
                return inner;
            }
            case ARRAY_START -> {
                return array();
            }
            case LBRACKET -> {
                return block();
            }
            default -> throw error(t, "expected an operand, found " + t.describe());
        }
    }

    private static Node path(Token t) {
        String text = t.text();
        boolean absolute = text.startsWith("/");
        String body = absolute ? text.substring(1) : text;
        return new Node.Name(t.pos(), text, Arrays.asList(body.split("/")), absolute);
    }

    private Node array() {
        Token start = advance();
        enter();
        try {
            List<Node> elements = new ArrayList<>();
            while (!check(TokenKind.RPAREN)) {
                if (check(TokenKind.EOF) || !startsOperand(peek())) {
                    throw error(peek(), "expected an operand or ')', found " + peek().describe());
                }
                elements.add(operand());
            }
            advance();
            return new Node.ArrayLiteral(start.pos(), elements);
        } finally {
            depth--;
        }
    }

    private Node block() {
        Token start = advance();
        List<String> params = new ArrayList<>();
        if (check(TokenKind.PARAM)) {
            while (check(TokenKind.PARAM)) {
                Token param = advance();
                if (params.contains(param.text())) {
                    throw error(param, "block parameter ':" + param.text() + "' is named twice; each parameter has a name of its own");
                }
                params.add(param.text());
            }
            Token bar = peek();
            if (bar.kind() != TokenKind.BINOP || !bar.text().equals("|")) {
                throw error(bar, "expected '|' after the block parameters, found " + bar.describe());
            }
            advance();
        }
        if (check(TokenKind.RBRACKET)) {
            throw error(peek(), "empty block: a block needs at least one statement");
        }
        List<Node> statements = new ArrayList<>();
        while (true) {
            statements.add(statement());
            if (match(TokenKind.RBRACKET)) {
                break;
            }
            expect(TokenKind.DOT, "'.' or ']'");
            if (match(TokenKind.RBRACKET)) {
                break;
            }
        }
        return new Node.BlockLiteral(start.pos(), params, statements);
    }

    private static boolean startsOperand(Token t) {
        return switch (t.kind()) {
            case NUMBER, STRING, BOOLEAN, IDENT, PATH, LPAREN, ARRAY_START, LBRACKET -> true;
            default -> false;
        };
    }

    private void enter() {
        if (++depth > MAX_NESTING) {
            depth--;
            errors.add(new SyntaxError(peek().pos(), "nesting deeper than " + MAX_NESTING + " levels"));
            throw new Abandon(true);
        }
    }

    private Token peek() {
        return current;
    }

    /** The token after the current one. */
    private Token peekNext() {
        if (following == null) {
            following = current.kind() == TokenKind.EOF ? current : lexer.next();
        }
        return following;
    }

    private boolean check(TokenKind kind) {
        return peek().kind() == kind;
    }

    private Token advance() {
        Token t = current;
        switch (t.kind()) {
            case EOF -> {
                return t;
            }
            case LPAREN, LBRACKET, ARRAY_START -> open.push(t.kind());
            case RPAREN -> {
                if (open.peek() == TokenKind.LPAREN || open.peek() == TokenKind.ARRAY_START) {
                    open.pop();
                }
            }
            case RBRACKET -> {
                // closes the innermost block, and whatever was left open inside it
                while (!open.isEmpty() && open.pop() != TokenKind.LBRACKET) {
                    // popped
                }
            }
            default -> {
            }
        }
        current = following != null ? following : lexer.next();
        following = null;
        return t;
    }

    private boolean match(TokenKind kind) {
        if (check(kind)) {
            advance();
            return true;
        }
        return false;
    }

    private void expect(TokenKind kind, String what) {
        if (!match(kind)) {
            throw error(peek(), "expected " + what + ", found " + peek().describe());
        }
    }

    private Abandon error(Token at, String message) {
        errors.add(new SyntaxError(at.pos(), message));
        return new Abandon(false);
    }
}
