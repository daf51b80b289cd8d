package net.smc.policy.lang;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.List;

/**
 * Turns PonderTalk source text into tokens (smc-policy/PONDERTALK.md section 2), one at a time as
 * the parser asks for them ({@link #next()}), so no list of a unit's tokens is ever held. Lexical
 * errors are added to the given list and the lexer carries on, so one pass reports every error of
 * a unit.
 */
public final class Lexer {
    private static final String BINOP_CHARS = "!%&*+/-<=>?@\\~,";
    /** Longest number literal accepted: parsing is superlinear in the digits. */
    static final int MAX_NUMBER_LENGTH = 1000;

    private final String source;
    private final String text;
    private final List<SyntaxError> errors;
    /** The kind of the last token produced, or {@code null} before the first. */
    private TokenKind last;
    /** The token {@link #scanToken} produced, or {@code null} when it only reported an error. */
    private Token scanned;
    private int index;
    private int line = 1;
    private int lineStart;

    /** A lexer over {@code text}, named {@code source} in positions; errors are added to {@code errors}. */
    Lexer(String source, String text, List<SyntaxError> errors) {
        this.source = source;
        this.text = text;
        this.errors = errors;
    }

    /** Lexes a whole unit into a list (for tests and tools); the last token is always {@link TokenKind#EOF}. */
    public static List<Token> tokenize(String source, String text, List<SyntaxError> errors) {
        Lexer lexer = new Lexer(source, text, errors);
        List<Token> tokens = new ArrayList<>();
        Token t;
        do {
            t = lexer.next();
            tokens.add(t);
        } while (t.kind() != TokenKind.EOF);
        return tokens;
    }

    /** The next token; at the end, {@link TokenKind#EOF} (again on every later call). */
    Token next() {
        while (true) {
            skipSpaceAndComments();
            if (index >= text.length()) {
                last = TokenKind.EOF;
                return new Token(TokenKind.EOF, "", null, pos(index));
            }
            scanned = null;
            scanToken();
            if (scanned != null) {
                last = scanned.kind();
                return scanned;
            }
        }
    }

    private SourcePos pos(int at) {
        return new SourcePos(source, line, at - lineStart + 1);
    }

    private char peek(int ahead) {
        int at = index + ahead;
        return at < text.length() ? text.charAt(at) : '\0';
    }

    /**
     * Whether the character at {@code at} ends a line: a line feed, or a carriage return that no line
     * feed follows (a file with the old Mac line ends has lines too, and a comment ends at each).
     */
    private boolean endsLine(int at) {
        char c = text.charAt(at);
        return c == '\n' || c == '\r' && (at + 1 >= text.length() || text.charAt(at + 1) != '\n');
    }

    private void skipSpaceAndComments() {
        while (index < text.length()) {
            char c = text.charAt(index);
            if (endsLine(index)) {
                index++;
                line++;
                lineStart = index;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f') {
                index++;
            } else if (c == '/' && peek(1) == '/') {
                while (index < text.length() && !endsLine(index)) {
                    index++;
                }
            } else {
                return;
            }
        }
    }

    private void scanToken() {
        int start = index;
        SourcePos at = pos(start);
        char c = text.charAt(index);
        if (isLetter(c)) {
            scanWord(start, at);
        } else if (isDigit(c) || (c == '-' && isDigit(peek(1)))) {
            scanNumber(start, at);
        } else if (c == '"') {
            scanString(at);
        } else if (c == '/' && isSegmentChar(peek(1)) && !previousEndsOperand()) {
            index++;
            scanPathRest(start, at);
        } else if (c == ':') {
            if (peek(1) == '=') {
                index += 2;
                add(TokenKind.ASSIGN, ":=", at);
            } else if (isLetter(peek(1))) {
                index++;
                int nameStart = index;
                while (index < text.length() && isSegmentChar(text.charAt(index))) {
                    index++;
                }
                add(TokenKind.PARAM, text.substring(nameStart, index), at);
            } else {
                index++;
                errors.add(new SyntaxError(at, "unexpected character ':'"));
            }
        } else if (c == '#' && peek(1) == '(') {
            index += 2;
            add(TokenKind.ARRAY_START, "#(", at);
        } else if (c == '|') {
            index++;
            add(TokenKind.BINOP, "|", at);
        } else if (BINOP_CHARS.indexOf(c) >= 0) {
            index++;
            while (index < text.length() && BINOP_CHARS.indexOf(text.charAt(index)) >= 0
                    && !(text.charAt(index) == '-' && isDigit(peek(1)))
                    && !(text.charAt(index) == '/' && peek(1) == '/')) {
                index++;
            }
            add(TokenKind.BINOP, text.substring(start, index), at);
        } else {
            index++;
            TokenKind single = switch (c) {
                case '.' -> TokenKind.DOT;
                case ';' -> TokenKind.SEMICOLON;
                case '(' -> TokenKind.LPAREN;
                case ')' -> TokenKind.RPAREN;
                case '[' -> TokenKind.LBRACKET;
                case ']' -> TokenKind.RBRACKET;
                default -> null;
            };
            if (single != null) {
                add(single, String.valueOf(c), at);
            } else {
                errors.add(new SyntaxError(at, "unexpected character " + describeChar(c)));
            }
        }
    }

    private static String describeChar(char c) {
        if (c < 32 || c > 126) {
            return String.format("U+%04X", (int) c);
        }
        return "'" + c + "'";
    }

    /** A leading '/' starts a path only where an operand is expected, not after one. */
    private boolean previousEndsOperand() {
        if (last == null) {
            return false;
        }
        return switch (last) {
            case IDENT, PATH, STRING, NUMBER, BOOLEAN, RPAREN, RBRACKET -> true;
            default -> false;
        };
    }

    private void scanWord(int start, SourcePos at) {
        while (index < text.length() && isSegmentChar(text.charAt(index))) {
            index++;
        }
        if (peek(0) == ':' && peek(1) != '=') {
            index++;
            add(TokenKind.KEYWORD, text.substring(start, index), at);
        } else if (peek(0) == '/' && isSegmentChar(peek(1))) {
            scanPathRest(start, at);
        } else {
            String word = text.substring(start, index);
            if (word.equals("true") || word.equals("false")) {
                emit(new Token(TokenKind.BOOLEAN, word, Boolean.valueOf(word), at));
            } else {
                add(TokenKind.IDENT, word, at);
            }
        }
    }

    /** Scans {@code /segment} parts after the first segment (or the leading '/'). */
    private void scanPathRest(int start, SourcePos at) {
        do {
            if (text.charAt(index) == '/') {
                index++;
            }
            while (index < text.length() && isSegmentChar(text.charAt(index))) {
                index++;
            }
        } while (peek(0) == '/' && isSegmentChar(peek(1)));
        add(TokenKind.PATH, text.substring(start, index), at);
    }

    private void scanNumber(int start, SourcePos at) {
        boolean negative = text.charAt(index) == '-';
        if (negative) {
            index++;
        }
        int digitsStart = index;
        if (peek(0) == '0' && (peek(1) == 'x' || peek(1) == 'X') && isHexDigit(peek(2))) {
            index += 2;
            int hexStart = index;
            while (isHexDigit(peek(0))) {
                index++;
            }
            if (tooLong(start, at)) {
                addNumber(start, at, BigDecimal.ZERO);   // refused already; stands in so the parser goes on
                return;
            }
            addNumber(start, at, negate(new BigDecimal(new BigInteger(text.substring(hexStart, index), 16)), negative));
            return;
        }
        while (isDigit(peek(0))) {
            index++;
        }
        if (peek(0) == 'r' && isRadixDigit(peek(1))) {
            int radix = parseRadix(text.substring(digitsStart, index), at);
            index++;
            int valueStart = index;
            while (isRadixDigit(peek(0))) {
                index++;
            }
            if (radix < 0 || tooLong(start, at)) {
                addNumber(start, at, BigDecimal.ZERO);   // refused already; stands in so the parser goes on
                return;
            }
            String digits = text.substring(valueStart, index);
            try {
                addNumber(start, at, negate(new BigDecimal(new BigInteger(digits, radix)), negative));
            } catch (NumberFormatException e) {
                errors.add(new SyntaxError(at, "invalid digits '" + digits + "' for radix " + radix));
                addNumber(start, at, BigDecimal.ZERO);
            }
            return;
        }
        if (peek(0) == '.' && isDigit(peek(1))) {
            index++;
            while (isDigit(peek(0))) {
                index++;
            }
        }
        if ((peek(0) == 'e' || peek(0) == 'E') && (isDigit(peek(1)) || (peek(1) == '-' && isDigit(peek(2))))) {
            index += 2;
            while (isDigit(peek(0))) {
                index++;
            }
        }
        if (tooLong(start, at)) {
            addNumber(start, at, BigDecimal.ZERO);   // refused already; stands in so the parser goes on
            return;
        }
        String written = text.substring(start, index);
        try {
            addNumber(start, at, new BigDecimal(written));
        } catch (NumberFormatException e) {
            errors.add(new SyntaxError(at, "number out of range '" + abbreviate(written) + "'"));
            addNumber(start, at, BigDecimal.ZERO);
        }
    }

    private int parseRadix(String digits, SourcePos at) {
        int radix = digits.length() > 2 ? Integer.MAX_VALUE : Integer.parseInt(digits);
        if (radix < 2 || radix > 36) {
            errors.add(new SyntaxError(at, "radix " + abbreviate(digits) + " is not between 2 and 36"));
            return -1;
        }
        return radix;
    }

    private static String abbreviate(String s) {
        return s.length() > 40 ? s.substring(0, 37) + "..." : s;
    }

    private static BigDecimal negate(BigDecimal value, boolean negative) {
        return negative ? value.negate() : value;
    }

    /** Whether the number from {@code start} to here is too long; reports it if so. */
    private boolean tooLong(int start, SourcePos at) {
        if (index - start > MAX_NUMBER_LENGTH) {
            errors.add(new SyntaxError(at, "number literal of " + (index - start) + " characters is longer than "
                    + MAX_NUMBER_LENGTH));
            return true;
        }
        return false;
    }

    private void addNumber(int start, SourcePos at, BigDecimal value) {
        emit(new Token(TokenKind.NUMBER, text.substring(start, index), value, at));
    }

    private void scanString(SourcePos at) {
        index++;
        StringBuilder value = new StringBuilder();
        while (index < text.length()) {
            char c = text.charAt(index);
            if (c == '"') {
                index++;
                String string = value.toString();
                emit(new Token(TokenKind.STRING, string, string, at));
                return;
            }
            if (c == '\\' && peek(1) == '"') {
                value.append('"');
                index += 2;
                continue;
            }
            if (endsLine(index)) {
                line++;
                lineStart = index + 1;
            }
            value.append(c);
            index++;
        }
        errors.add(new SyntaxError(at, "unterminated string"));
    }

    private void emit(Token token) {
        scanned = token;
    }

    private void add(TokenKind kind, String tokenText, SourcePos at) {
        emit(new Token(kind, tokenText, null, at));
    }

    static boolean isLetter(char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    }

    static boolean isDigit(char c) {
        return c >= '0' && c <= '9';
    }

    private static boolean isHexDigit(char c) {
        return isDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
    }

    private static boolean isRadixDigit(char c) {
        return isDigit(c) || (c >= 'A' && c <= 'Z');
    }

    static boolean isSegmentChar(char c) {
        return isLetter(c) || isDigit(c) || c == '_';
    }
}
