package net.smc.policy.lang;

/** The kinds of token the {@link Lexer} produces. */
public enum TokenKind {
    /** A name such as {@code root} or {@code trueCount}; {@code true} and {@code false} are {@link #BOOLEAN}. */
    IDENT,
    /** A keyword part such as {@code at:}; the text includes the colon. */
    KEYWORD,
    /** A block parameter such as {@code :x}; the text excludes the colon. */
    PARAM,
    /** {@code :=}. */
    ASSIGN,
    /** A path such as {@code root/event/alarm} or {@code /event/alarm}. */
    PATH,
    /** A string literal; the text is the value with escapes resolved. */
    STRING,
    /** A number literal; the text is as written. */
    NUMBER,
    /** {@code true} or {@code false}. */
    BOOLEAN,
    /** A binary operator such as {@code +}, {@code <=} or {@code |}. */
    BINOP,
    DOT,
    SEMICOLON,
    LPAREN,
    RPAREN,
    /** {@code #(}, which opens an array literal. */
    ARRAY_START,
    LBRACKET,
    RBRACKET,
    /** The end of the unit. */
    EOF
}
