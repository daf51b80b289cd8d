package net.smc.policy.lang;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The lexical rules of smc-policy/PONDERTALK.md section 2: token kinds, values, positions and lexical errors. */
class LexerTest {
    private static final String SOURCE = "t.p2";

    /** Lexes text that must have no lexical errors. */
    private static List<Token> lex(String text) {
        List<SyntaxError> errors = new ArrayList<>();
        List<Token> tokens = Lexer.tokenize(SOURCE, text, errors);
        assertEquals(List.of(), errors, "lexical errors of " + text);
        return tokens;
    }

    private static List<SyntaxError> errorsOf(String text) {
        List<SyntaxError> errors = new ArrayList<>();
        Lexer.tokenize(SOURCE, text, errors);
        return errors;
    }

    /** Each token (EOF excluded) as KIND:text@line:column. */
    private static List<String> described(String text) {
        List<String> out = new ArrayList<>();
        for (Token t : lex(text)) {
            if (t.kind() != TokenKind.EOF) {
                out.add(t.kind() + ":" + t.text() + "@" + t.pos().line() + ":" + t.pos().column());
            }
        }
        return out;
    }

    private static List<TokenKind> kinds(String text) {
        return lex(text).stream().map(Token::kind).toList();
    }

    private static Token single(String text) {
        List<Token> tokens = lex(text);
        assertEquals(2, tokens.size(), "one token and EOF in " + tokens);
        return tokens.get(0);
    }

    private static BigDecimal number(String text) {
        Token t = single(text);
        assertEquals(TokenKind.NUMBER, t.kind(), text);
        return (BigDecimal) t.value();
    }

    // ---- every token kind, with positions ----

    @Test
    void identifier_isOneTokenStartingAtColumnOne() {
        assertEquals(List.of("IDENT:abc_1Z@1:1"), described("abc_1Z"));
    }

    @Test
    void emptyText_isJustEofAtLineOneColumnOne() {
        List<Token> tokens = lex("");
        assertEquals(1, tokens.size());
        assertEquals(TokenKind.EOF, tokens.get(0).kind());
        assertEquals(new SourcePos(SOURCE, 1, 1), tokens.get(0).pos());
    }

    @Test
    void eof_isAlwaysLastAndSitsJustAfterTheText() {
        List<Token> tokens = lex("ab\ncd ");
        Token eof = tokens.get(tokens.size() - 1);
        assertEquals(TokenKind.EOF, eof.kind());
        assertEquals(new SourcePos(SOURCE, 2, 4), eof.pos());
    }

    @Test
    void trueAndFalse_areBooleanLiteralsWithBooleanValues() {
        List<Token> tokens = lex("true false");
        assertEquals(TokenKind.BOOLEAN, tokens.get(0).kind());
        assertEquals(Boolean.TRUE, tokens.get(0).value());
        assertEquals(TokenKind.BOOLEAN, tokens.get(1).kind());
        assertEquals(Boolean.FALSE, tokens.get(1).value());
    }

    @Test
    void wordsThatStartWithTrue_areIdentifiers() {
        assertEquals(List.of("IDENT:trueCount@1:1", "IDENT:falsey@1:11", "IDENT:nil@1:18"),
                described("trueCount falsey nil"));
    }

    @Test
    void keyword_isANameGluedToAColonAndKeepsTheColon() {
        assertEquals(List.of("IDENT:d@1:1", "KEYWORD:at:@1:3", "NUMBER:1@1:7", "KEYWORD:put:@1:9", "NUMBER:2@1:14"),
                described("d at: 1 put: 2"));
    }

    @Test
    void keywordsWrittenWithoutSpaces_areSeparateKeywordTokens() {
        assertEquals(List.of("KEYWORD:at:@1:1", "KEYWORD:put:@1:4"), described("at:put:"));
    }

    @Test
    void assignment_gluedToTheName_isNameThenAssign() {
        assertEquals(List.of("IDENT:x@1:1", "ASSIGN::=@1:2", "NUMBER:1@1:4"), described("x:=1"));
    }

    @Test
    void assignment_withSpaces_isNameThenAssign() {
        assertEquals(List.of("IDENT:x@1:1", "ASSIGN::=@1:3", "NUMBER:1@1:6"), described("x := 1"));
    }

    @Test
    void blockParameter_isColonGluedToANameAndDropsTheColon() {
        assertEquals(List.of("LBRACKET:[@1:1", "PARAM:x@1:2", "PARAM:y_2@1:5", "BINOP:|@1:10", "IDENT:x@1:12",
                "RBRACKET:]@1:13"), described("[:x :y_2 | x]"));
    }

    @Test
    void punctuation_eachKindIsOneToken() {
        assertEquals(List.of("DOT:.@1:1", "SEMICOLON:;@1:2", "LPAREN:(@1:3", "RPAREN:)@1:4", "LBRACKET:[@1:5",
                "RBRACKET:]@1:6", "ARRAY_START:#(@1:7"), described(".;()[]#("));
    }

    @Test
    void arrayStart_isHashGluedToAParenthesis() {
        assertEquals(List.of(TokenKind.ARRAY_START, TokenKind.NUMBER, TokenKind.RPAREN, TokenKind.EOF), kinds("#(1)"));
    }

    @Test
    void hashFollowedBySpace_isAnUnexpectedCharacter() {
        assertEquals(List.of(new SyntaxError(new SourcePos(SOURCE, 1, 1), "unexpected character '#'")),
                errorsOf("# (1)"));
    }

    @Test
    void everyTokenKind_isProducedByTheLexer() {
        String all = "x := \"s\" at: 1 + root/a true. [:p | p]; (#(2))";
        List<TokenKind> seen = kinds(all);
        for (TokenKind kind : TokenKind.values()) {
            assertTrue(seen.contains(kind), kind + " in " + seen);
        }
    }

    // ---- positions ----

    @Test
    void positions_countLinesAndColumnsFromOneAcrossNewlines() {
        assertEquals(List.of("IDENT:a@1:1", "IDENT:b@2:3", "IDENT:c@4:5"), described("a\n  b\n\n    c"));
    }

    @Test
    void positions_tabCountsAsOneColumn() {
        assertEquals(List.of("IDENT:a@1:2", "IDENT:b@1:4"), described("\ta\tb"));
    }

    @Test
    void positions_crlfLineEndsCountAsOneLine() {
        assertEquals(List.of("IDENT:a@1:1", "IDENT:b@2:1"), described("a\r\nb"));
    }

    @Test
    void positions_afterAMultiLineStringContinueOnItsLastLine() {
        List<Token> tokens = lex("x := \"one\ntwo\nthree\" y.\nz");
        assertEquals(new SourcePos(SOURCE, 1, 6), tokens.get(2).pos(), "the string starts at its quote");
        assertEquals("one\ntwo\nthree", tokens.get(2).value());
        assertEquals(new SourcePos(SOURCE, 3, 8), tokens.get(3).pos(), "y after the string");
        assertEquals(new SourcePos(SOURCE, 3, 9), tokens.get(4).pos(), "the dot");
        assertEquals(new SourcePos(SOURCE, 4, 1), tokens.get(5).pos(), "z on the next line");
    }

    @Test
    void positions_carryTheSourceName() {
        List<SyntaxError> errors = new ArrayList<>();
        Token t = Lexer.tokenize("boot.p2", "x", errors).get(0);
        assertEquals("boot.p2", t.pos().source());
        assertEquals("boot.p2:1:1", t.pos().toString());
    }

    // ---- paths ----

    @Test
    void path_isNameWithSlashSegmentsAndNoSpaces() {
        assertEquals(List.of("PATH:root/event/alarm@1:1"), described("root/event/alarm"));
    }

    @Test
    void path_segmentsMayHoldDigitsAndUnderscores() {
        assertEquals(List.of("PATH:d/sub_1/x2@1:1"), described("d/sub_1/x2"));
    }

    @Test
    void path_withLeadingSlashAtTheStart_isAnAbsolutePath() {
        assertEquals(List.of("PATH:/event/newUAV@1:1"), described("/event/newUAV"));
    }

    @Test
    void path_withLeadingSlashAfterAKeyword_isAPath() {
        assertEquals(List.of("IDENT:root@1:1", "KEYWORD:print:@1:6", "PATH:/a/b@1:13"), described("root print: /a/b"));
    }

    @Test
    void path_withLeadingSlashAfterAnOpeningParenthesis_isAPath() {
        assertEquals(List.of("LPAREN:(@1:1", "PATH:/a@1:2", "RPAREN:)@1:4"), described("(/a)"));
    }

    @Test
    void path_withLeadingSlashAfterAStatementDot_isAPath() {
        assertEquals(List.of("NUMBER:1@1:1", "DOT:.@1:2", "PATH:/a@1:4"), described("1. /a"));
    }

    @Test
    void path_withLeadingSlashAfterABinaryOperator_isAPath() {
        assertEquals(List.of("NUMBER:1@1:1", "BINOP:+@1:3", "PATH:/a/b@1:5"), described("1 + /a/b"));
    }

    @Test
    void path_withLeadingSlashAfterAssignment_isAPath() {
        assertEquals(List.of("IDENT:x@1:1", "ASSIGN::=@1:3", "PATH:/a@1:6"), described("x := /a"));
    }

    @Test
    void slashAfterAnIdentifier_isDivision() {
        assertEquals(List.of("IDENT:a@1:1", "BINOP:/@1:3", "IDENT:b@1:4"), described("a /b"));
    }

    @Test
    void slashBetweenNumbers_isDivision() {
        assertEquals(List.of("NUMBER:6@1:1", "BINOP:/@1:2", "NUMBER:2@1:3"), described("6/2"));
    }

    @Test
    void slashAfterAClosingParenthesis_isDivision() {
        assertEquals(List.of("LPAREN:(@1:1", "IDENT:a@1:2", "RPAREN:)@1:3", "BINOP:/@1:5", "IDENT:b@1:6"),
                described("(a) /b"));
    }

    @Test
    void slashAfterAString_isDivision() {
        assertEquals(List.of(TokenKind.STRING, TokenKind.BINOP, TokenKind.IDENT, TokenKind.EOF), kinds("\"s\" /b"));
    }

    @Test
    void slashAfterABlock_isDivision() {
        assertEquals(List.of(TokenKind.LBRACKET, TokenKind.NUMBER, TokenKind.RBRACKET, TokenKind.BINOP,
                TokenKind.IDENT, TokenKind.EOF), kinds("[1] /b"));
    }

    @Test
    void slashAtTheEndOfAName_isNotPartOfThePath() {
        assertEquals(List.of("IDENT:a@1:1", "BINOP:/@1:2"), described("a/"));
    }

    // ---- minus and numbers ----

    @Test
    void minusGluedToDigits_isPartOfTheNumber() {
        assertEquals(new BigDecimal("-2"), number("-2"));
    }

    @Test
    void numberThenSpaceThenGluedMinus_isTwoNumbers() {
        assertEquals(List.of("NUMBER:3@1:1", "NUMBER:-2@1:3"), described("3 -2"));
    }

    @Test
    void numberThenGluedMinus_isTwoNumbers() {
        assertEquals(List.of("NUMBER:3@1:1", "NUMBER:-2@1:2"), described("3-2"));
    }

    @Test
    void nameThenGluedMinus_isNameThenNegativeNumber() {
        assertEquals(List.of("IDENT:x@1:1", "NUMBER:-1@1:2"), described("x-1"));
    }

    @Test
    void minusWithSpaces_isABinaryOperator() {
        assertEquals(List.of("NUMBER:3@1:1", "BINOP:-@1:3", "NUMBER:2@1:5"), described("3 - 2"));
    }

    @Test
    void binaryOperatorThenNegativeNumber_isOperatorThenNumber() {
        assertEquals(List.of("NUMBER:5@1:1", "BINOP:+@1:3", "NUMBER:-3@1:5"), described("5 + -3"));
    }

    @Test
    void binaryOperatorGluedToNegativeNumber_stopsBeforeTheMinus() {
        assertEquals(List.of("NUMBER:5@1:1", "BINOP:+@1:2", "NUMBER:-3@1:3"), described("5+-3"));
    }

    @Test
    void minusBeforeANonDigit_isAnOperator() {
        assertEquals(List.of("BINOP:-@1:1", "IDENT:x@1:2"), described("-x"));
    }

    @Test
    void integer_valueIsABigDecimal() {
        Token t = single("42");
        assertEquals(TokenKind.NUMBER, t.kind());
        assertEquals("42", t.text());
        assertEquals(new BigDecimal("42"), t.value());
    }

    @Test
    void decimal_keepsItsScale() {
        assertEquals(new BigDecimal("3.140"), number("3.140"));
    }

    @Test
    void exponent_isPartOfTheNumber() {
        BigDecimal n = number("1.5e2");
        assertEquals(new BigDecimal("1.5e2"), n);
        assertEquals("1.5E+2", n.toString());
    }

    @Test
    void negativeExponent_isPartOfTheNumber() {
        assertEquals(new BigDecimal("0.001"), number("1e-3"));
    }

    @Test
    void upperCaseExponent_isPartOfTheNumber() {
        assertEquals(new BigDecimal("1E3"), number("1E3"));
    }

    @Test
    void negativeNumberWithFractionAndExponent_isOneNumber() {
        assertEquals(new BigDecimal("-1.5e-2"), number("-1.5e-2"));
    }

    @Test
    void exponentLetterWithoutDigits_isANumberThenAName() {
        assertEquals(List.of("NUMBER:2@1:1", "IDENT:e@1:2"), described("2e"));
    }

    @Test
    void dotWithoutDigitsAfterANumber_endsTheStatement() {
        assertEquals(List.of("NUMBER:1@1:1", "DOT:.@1:2", "IDENT:x@1:3"), described("1.x"));
    }

    @Test
    void radixNumber_isReadInItsBase() {
        Token t = single("16r1F");
        assertEquals("16r1F", t.text());
        assertEquals(new BigDecimal(31), t.value());
    }

    @Test
    void radixNumber_binaryAndBase36() {
        assertEquals(new BigDecimal(10), number("2r1010"));
        assertEquals(new BigDecimal(35), number("36rZ"));
    }

    @Test
    void radixNumber_withMinus_isNegative() {
        assertEquals(new BigDecimal(-31), number("-16r1F"));
    }

    @Test
    void hexNumber_isReadInBaseSixteen() {
        assertEquals(new BigDecimal(31), number("0x1f"));
        assertEquals(new BigDecimal(31), number("0X1F"));
    }

    @Test
    void hexPrefixWithoutDigits_isZeroThenAName() {
        assertEquals(List.of("NUMBER:0@1:1", "IDENT:xg@1:2"), described("0xg"));
    }

    // ---- binary operators ----

    @ParameterizedTest
    @ValueSource(strings = {"+", "-", "*", "/", "<", ">", "=", "<=", ">=", "==", "!=", "~=", "->", "&", "@", "%",
            "?", "\\", "~", ",", "!", "+*/"})
    void binaryOperator_runOfOperatorCharactersIsOneToken(String op) {
        Token t = single(op);
        assertEquals(TokenKind.BINOP, t.kind());
        assertEquals(op, t.text());
    }

    @Test
    void binaryOperator_betweenOperandsKeepsItsPosition() {
        assertEquals(List.of("IDENT:a@1:1", "BINOP:<=@1:3", "IDENT:b@1:6"), described("a <= b"));
    }

    @Test
    void bar_isAlwaysASingleCharacterOperator() {
        assertEquals(List.of("BINOP:|@1:1", "BINOP:|@1:2"), described("||"));
    }

    @Test
    void bar_doesNotJoinOtherOperatorCharacters() {
        assertEquals(List.of("BINOP:|@1:1", "BINOP:=@1:2"), described("|="));
    }

    @Test
    void operatorRun_stopsAtAComment() {
        assertEquals(List.of("NUMBER:1@1:1", "BINOP:+@1:3", "NUMBER:2@2:1"), described("1 +// comment\n2"));
    }

    // ---- strings ----

    @Test
    void string_valueIsTheTextBetweenTheQuotes() {
        Token t = single("\"hello world\"");
        assertEquals(TokenKind.STRING, t.kind());
        assertEquals("hello world", t.value());
        assertEquals(new SourcePos(SOURCE, 1, 1), t.pos());
    }

    @Test
    void string_escapedQuoteIsAQuote() {
        assertEquals("say \"hi\"", single("\"say \\\"hi\\\"\"").value());
    }

    @Test
    void string_otherBackslashesAreLiteral() {
        assertEquals("a\\b\\nc\\\\d", single("\"a\\b\\nc\\\\d\"").value());
    }

    @Test
    void string_mayHoldNewlines() {
        assertEquals("a\nb", single("\"a\nb\"").value());
    }

    @Test
    void string_emptyIsAnEmptyValue() {
        assertEquals("", single("\"\"").value());
    }

    @Test
    void string_commentMarkersInsideAreText() {
        assertEquals("// not a comment", single("\"// not a comment\"").value());
    }

    // ---- comments ----

    @Test
    void comment_runsToTheEndOfTheLine() {
        assertEquals(List.of("NUMBER:1@1:1", "NUMBER:2@2:1"), described("1 // one \"two\n2"));
    }

    @Test
    void comment_onALastLineWithoutNewline_isAccepted() {
        assertEquals(List.of("NUMBER:1@1:1"), described("1 // the end"));
    }

    @Test
    void comment_aloneIsJustEof() {
        assertEquals(List.of(TokenKind.EOF), kinds("// only a comment"));
    }

    @Test
    void comment_afterANameIsNotAPath() {
        assertEquals(List.of("IDENT:a@1:1", "IDENT:b@2:1"), described("a//b\nb"));
    }

    // ---- errors ----

    @Test
    void characterLiteral_isAnUnexpectedCharacter() {
        List<SyntaxError> errors = new ArrayList<>();
        List<Token> tokens = Lexer.tokenize(SOURCE, "$a", errors);
        assertEquals(List.of(new SyntaxError(new SourcePos(SOURCE, 1, 1), "unexpected character '$'")), errors);
        assertEquals(TokenKind.IDENT, tokens.get(0).kind());
        assertEquals(new SourcePos(SOURCE, 1, 2), tokens.get(0).pos());
    }

    @Test
    void nonAsciiCharacter_isNamedByItsCodePoint() {
        assertEquals(List.of(new SyntaxError(new SourcePos(SOURCE, 1, 3), "unexpected character U+00E9")),
                errorsOf("a \u00e9"));
    }

    @Test
    void loneColon_isAnUnexpectedCharacter() {
        assertEquals(List.of(new SyntaxError(new SourcePos(SOURCE, 1, 3), "unexpected character ':'")),
                errorsOf("a : b"));
    }

    @Test
    void unterminatedString_isReportedAtItsOpeningQuote() {
        assertEquals(List.of(new SyntaxError(new SourcePos(SOURCE, 1, 6), "unterminated string")),
                errorsOf("x := \"abc"));
    }

    @Test
    void unterminatedMultiLineString_isReportedAtItsOpeningQuote() {
        assertEquals(List.of(new SyntaxError(new SourcePos(SOURCE, 2, 3), "unterminated string")),
                errorsOf("x.\ny \"abc\ndef\n"));
    }

    @Test
    void stringEndingInAnEscapedQuote_isUnterminated() {
        assertEquals(List.of(new SyntaxError(new SourcePos(SOURCE, 1, 1), "unterminated string")),
                errorsOf("\"abc\\\""));
    }

    @ParameterizedTest
    @ValueSource(strings = {"40r1", "1r0", "0r0", "37rZ"})
    void radixOutOfRange_isAnError(String text) {
        String radix = text.substring(0, text.indexOf('r'));
        assertEquals(List.of(new SyntaxError(new SourcePos(SOURCE, 1, 1), "radix " + radix + " is not between 2 and 36")),
                errorsOf(text));
    }

    @Test
    void radixWithManyDigits_isAnErrorNotACrash() {
        assertEquals(List.of(new SyntaxError(new SourcePos(SOURCE, 1, 3),
                "radix 99999999999999999999 is not between 2 and 36")), errorsOf("1 99999999999999999999r1"));
    }

    @Test
    void radixDigitsOutsideTheBase_isAnError() {
        assertEquals(List.of(new SyntaxError(new SourcePos(SOURCE, 1, 1), "invalid digits '12' for radix 2")),
                errorsOf("2r12"));
    }

    @Test
    void exponentTooLarge_isAnError() {
        List<SyntaxError> errors = errorsOf("1e99999999999");
        assertEquals(1, errors.size(), errors.toString());
        assertEquals("number out of range '1e99999999999'", errors.get(0).message());
    }

    @Test
    void lexer_continuesAfterErrorsAndReportsThemAll() {
        List<SyntaxError> errors = new ArrayList<>();
        List<Token> tokens = Lexer.tokenize(SOURCE, "a $ b ^ c 40r1\n  d \"open", errors);
        assertEquals(List.of(
                new SyntaxError(new SourcePos(SOURCE, 1, 3), "unexpected character '$'"),
                new SyntaxError(new SourcePos(SOURCE, 1, 7), "unexpected character '^'"),
                new SyntaxError(new SourcePos(SOURCE, 1, 11), "radix 40 is not between 2 and 36"),
                new SyntaxError(new SourcePos(SOURCE, 2, 5), "unterminated string")), errors);
        // a refused number stays as a token (value 0), so that the parser reports nothing more about it
        assertEquals(List.of("a", "b", "c", "40r1", "d", ""), tokens.stream().map(Token::text).toList());
    }

    /** Old Mac line ends (a carriage return alone) end lines and comments as line feeds do. */
    @Test
    void aCarriageReturnAlone_endsALineAndAComment() {
        List<SyntaxError> errors = new ArrayList<>();
        List<Token> tokens = Lexer.tokenize(SOURCE, "a // note\rb\r\nc\r  \"x\ry\" d", errors);
        assertEquals(List.of(), errors);
        assertEquals(List.of("a", "b", "c", "x\ry", "d", ""), tokens.stream().map(Token::text).toList());
        assertEquals(List.of(1, 2, 3, 4, 5), tokens.subList(0, 5).stream().map(t -> t.pos().line()).toList());
        assertEquals(3, tokens.get(3).pos().column(), "columns count from the line's start");
    }

    @Test
    void nonNumberTokens_haveNoValue() {
        for (Token t : lex("a at: :p := root/x + ( ) [ ] #( . ;")) {
            assertNull(t.value(), t.toString());
        }
    }

    @Test
    void tokens_areLexedOnDemand_notAheadOfTheReader() {
        List<SyntaxError> errors = new ArrayList<>();
        Lexer lexer = new Lexer(SOURCE, "a b $", errors);

        assertEquals("a", lexer.next().text());
        assertEquals("b", lexer.next().text());
        assertEquals(List.of(), errors, "the '$' after b is not read yet");
        assertEquals(TokenKind.EOF, lexer.next().kind());
        assertEquals(1, errors.size());
        assertEquals(TokenKind.EOF, lexer.next().kind(), "the end answers EOF again");
    }
}
