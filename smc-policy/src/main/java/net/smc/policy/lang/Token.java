package net.smc.policy.lang;

/**
 * One token of PonderTalk source. For numbers, {@code value} holds the parsed
 * {@link java.math.BigDecimal}; for strings, the string; otherwise it is {@code null}.
 */
public record Token(TokenKind kind, String text, Object value, SourcePos pos) {

    /** How the token is named in a syntax error: its text in quotes, or "end of input". */
    public String describe() {
        if (kind == TokenKind.EOF) {
            return "end of input";
        }
        String shown = kind == TokenKind.STRING ? '"' + text + '"' : text;
        if (shown.length() > 40) {
            shown = shown.substring(0, 37) + "...";
        }
        return "'" + shown + "'";
    }
}
