package net.smc.policy.lang;

import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Parses a PonderTalk unit into {@link Node}s (grammar: smc-policy/PONDERTALK.md section 3). The parser
 * recovers at statement boundaries, so one call reports every syntax error of the unit; it bounds
 * nesting so that no input can exhaust the stack.
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

    private final List<Token> tokens;
    private final List<SyntaxError> errors;
    private final IncludeResolver includes;
    private final int includeDepth;
    private int current;
    private int depth;
    /** Brackets opened and not yet closed by the tokens consumed so far. */
    private int open;
    /** How deep each send built so far is (sends are built left to right, so receivers come first). */
    private final java.util.IdentityHashMap<Node, Integer> sendDepths = new java.util.IdentityHashMap<>();

    private Parser(List<Token> tokens, List<SyntaxError> errors, IncludeResolver includes, int includeDepth) {
        this.tokens = tokens;
        this.errors = errors;
        this.includes = includes;
        this.includeDepth = includeDepth;
    }

    /** Parses a unit that may not include files. */
    public static Unit parse(String source, String text) {
        return parse(source, text, IncludeResolver.NONE);
    }

    /** Parses a unit; {@code include "file"} statements are resolved with {@code includes}. */
    public static Unit parse(String source, String text, IncludeResolver includes) {
        List<SyntaxError> errors = new ArrayList<>();
        List<Node> statements = parseInto(source, text, includes, 0, errors);
        if (errors.size() > MAX_ERRORS) {
            int all = errors.size();
            List<SyntaxError> shown = new ArrayList<>(errors.subList(0, MAX_ERRORS));
            shown.add(new SyntaxError(errors.get(MAX_ERRORS).pos(),
                    "too many syntax errors (" + all + "); only the first " + MAX_ERRORS + " are listed"));
            errors = shown;
        }
        return new Unit(source, statements, errors);
    }

    private static List<Node> parseInto(String source, String text, IncludeResolver includes, int includeDepth,
                                        List<SyntaxError> errors) {
        List<Token> tokens = Lexer.tokenize(source, text, errors);
        return new Parser(tokens, errors, includes, includeDepth).unit();
    }

    /** Thrown to abandon the current statement after an error has been recorded. */
    private static final class Abandon extends RuntimeException {
        final boolean wholeUnit;

        Abandon(boolean wholeUnit) {
            super(null, null, false, false);
            this.wholeUnit = wholeUnit;
        }
    }

    private List<Node> unit() {
        List<Node> statements = new ArrayList<>();
        while (!check(TokenKind.EOF)) {
            if (errors.size() > MAX_ERRORS) {
                break;
            }
            try {
                topStatement(statements);
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
        return statements;
    }

    private void topStatement(List<Node> statements) {
        Token first = peek();
        if (first.kind() == TokenKind.IDENT && first.text().equals("include")
                && peekAt(1).kind() == TokenKind.STRING) {
            advance();
            Token name = advance();
            include(name, statements);
            return;
        }
        statements.add(statement());
    }

    private void include(Token name, List<Node> statements) {
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
        statements.addAll(parseInto(included.source(), included.text(), includes, includeDepth + 1, errors));
    }

    /** Skips to just after the next '.' that ends a top-level statement, or to the end. */
    private void synchronize() {
        while (!check(TokenKind.EOF)) {
            Token t = advance();
            if (t.kind() == TokenKind.DOT && open == 0) {
                return;
            }
        }
    }

    private Node statement() {
        enter();
        try {
            Token first = peek();
            if (peekAt(1).kind() == TokenKind.ASSIGN) {
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
                params.add(advance().text());
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
        return tokens.get(current);
    }

    private Token peekAt(int ahead) {
        return tokens.get(Math.min(current + ahead, tokens.size() - 1));
    }

    private boolean check(TokenKind kind) {
        return peek().kind() == kind;
    }

    private Token advance() {
        Token t = tokens.get(current);
        switch (t.kind()) {
            case EOF -> {
                return t;
            }
            case LPAREN, LBRACKET, ARRAY_START -> open++;
            case RPAREN, RBRACKET -> open = Math.max(0, open - 1);
            default -> {
            }
        }
        current++;
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
