package net.smc.policy.lang;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** The grammar of smc-policy/PONDERTALK.md section 3: tree shapes, syntax errors, recovery, limits and includes. */
class ParserTest {
    private static final String SOURCE = "t.p2";

    private static Unit parse(String text) {
        return Parser.parse(SOURCE, text);
    }

    /** Parses text that must be free of errors. */
    private static List<Node> statements(String text) {
        Unit unit = parse(text);
        assertEquals(List.of(), unit.errors(), "syntax errors of " + text);
        return unit.statements();
    }

    private static Node only(String text) {
        List<Node> all = statements(text);
        assertEquals(1, all.size(), "statements of " + text);
        return all.get(0);
    }

    /** The tree of one statement in a compact bracketed form, for comparing shapes. */
    private static String tree(String text) {
        return show(only(text));
    }

    private static List<SyntaxError> errors(String text) {
        return parse(text).errors();
    }

    private static SyntaxError oneError(String text) {
        List<SyntaxError> all = errors(text);
        assertEquals(1, all.size(), "errors of " + text + ": " + all);
        return all.get(0);
    }

    private static SourcePos at(int line, int column) {
        return new SourcePos(SOURCE, line, column);
    }

    static String show(Node node) {
        if (node instanceof Node.Literal lit) {
            return lit.value() instanceof String s ? '"' + s + '"' : String.valueOf(lit.value());
        }
        if (node instanceof Node.Name name) {
            return name.text();
        }
        if (node instanceof Node.Assign assign) {
            return "(" + assign.name() + " := " + show(assign.value()) + ")";
        }
        if (node instanceof Node.ArrayLiteral array) {
            return array.elements().stream().map(ParserTest::show).collect(Collectors.joining(" ", "#(", ")"));
        }
        if (node instanceof Node.BlockLiteral block) {
            String params = block.params().stream().map(p -> ":" + p + " ").collect(Collectors.joining());
            return "[" + params + (params.isEmpty() ? "" : "| ")
                    + block.statements().stream().map(ParserTest::show).collect(Collectors.joining(". ")) + "]";
        }
        if (node instanceof Node.Send send) {
            return "(" + show(send.receiver()) + " " + show(send.message()) + ")";
        }
        Node.Cascade cascade = (Node.Cascade) node;
        return "(" + show(cascade.receiver()) + cascade.chains().stream()
                .map(chain -> chain.stream().map(ParserTest::show).collect(Collectors.joining(", ")))
                .collect(Collectors.joining("; ", " {", "}")) + ")";
    }

    private static String show(Node.Message m) {
        return m.selector() + m.args().stream().map(a -> " " + show(a)).collect(Collectors.joining());
    }

    // ---- precedence ----

    @Test
    void binaryOperators_shareOneLevelAndAssociateLeft() {
        Node.Send times = assertInstanceOf(Node.Send.class, only("2 + 3 * 4"));
        assertEquals("*", times.message().selector());
        assertEquals(List.of(new BigDecimal(4)), times.message().args().stream().map(a -> ((Node.Literal) a).value()).toList());
        Node.Send plus = assertInstanceOf(Node.Send.class, times.receiver());
        assertEquals("+", plus.message().selector());
        assertEquals(new BigDecimal(2), ((Node.Literal) plus.receiver()).value());
        assertEquals(new BigDecimal(3), ((Node.Literal) plus.message().args().get(0)).value());
    }

    @Test
    void unaryMessages_bindTighterThanBinary() {
        assertEquals("((a foo) + (b bar))", tree("a foo + b bar"));
    }

    @Test
    void unaryMessages_chainLeftToRight() {
        assertEquals("(((a b) c) d)", tree("a b c d"));
    }

    @Test
    void binaryMessages_bindTighterThanKeyword() {
        assertEquals("(d at:put: (1 + 2) (x size))", tree("d at: 1 + 2 put: x size"));
    }

    @Test
    void keywordMessage_followsUnaryAndBinaryOfItsReceiver() {
        assertEquals("(((a b) + 1) c: d)", tree("a b + 1 c: d"));
    }

    @Test
    void keywordParts_joinAcrossTheStatementIntoOneSelector() {
        Node.Send send = assertInstanceOf(Node.Send.class, only("root print: #(1 2) at: 9 put: 1"));
        assertEquals("print:at:put:", send.message().selector());
        assertEquals(3, send.message().args().size());
        assertEquals("root", ((Node.Name) send.receiver()).text());
    }

    @Test
    void parentheses_groupAStatement() {
        assertEquals("(2 + (3 * 4))", tree("2 + (3 * 4)"));
    }

    @Test
    void parenthesisedKeywordMessage_isAnArgument() {
        assertEquals("(a at:put: (b at: 1) 2)", tree("a at: (b at: 1) put: 2"));
    }

    @Test
    void messagePosition_isItsSelectorToken() {
        Node.Send send = assertInstanceOf(Node.Send.class, only("root\n  print: 1"));
        assertEquals(at(2, 3), send.pos());
        assertEquals(at(1, 1), send.receiver().pos());
    }

    // ---- cascades ----

    @Test
    void cascade_receiverIsTheReceiverOfTheLastMessageOfTheFirstPart() {
        Node.Cascade cascade = assertInstanceOf(Node.Cascade.class, only("(3 + 4 + 5; * 10)"));
        assertEquals("(3 + 4)", show(cascade.receiver()));
        assertEquals(2, cascade.chains().size());
        assertEquals("+ 5", show(cascade.chains().get(0).get(0)));
        assertEquals("* 10", show(cascade.chains().get(1).get(0)));
        assertEquals(List.of(1, 1), cascade.chains().stream().map(List::size).toList());
    }

    @Test
    void cascade_ofKeywordMessagesSharesTheReceiver() {
        assertEquals("(d {at:put: \"a\" 1; at:put: \"b\" 2; size})", tree("d at: \"a\" put: 1; at: \"b\" put: 2; size"));
    }

    @Test
    void cascade_partMayBeAChainOfMessages() {
        assertEquals("((r m1) {m2; m3, m4})", tree("r m1 m2; m3 m4"));
    }

    @Test
    void cascade_positionIsItsFirstMessage() {
        Node.Cascade cascade = assertInstanceOf(Node.Cascade.class, only("x foo; bar"));
        assertEquals(at(1, 3), cascade.pos());
    }

    @Test
    void cascade_withoutAMessageBeforeTheSemicolon_isAnError() {
        SyntaxError error = oneError("a; b");
        assertEquals(at(1, 2), error.pos());
        assertEquals("expected a message before ';', found ';'", error.message());
    }

    @Test
    void cascade_withAnEmptyPart_isAnError() {
        SyntaxError error = oneError("a foo; .");
        assertEquals(at(1, 8), error.pos());
        assertEquals("expected a message after ';', found '.'", error.message());
    }

    // ---- assignment ----

    @Test
    void assignment_chainsToTheRight() {
        Node.Assign a = assertInstanceOf(Node.Assign.class, only("a := b := 5"));
        assertEquals("a", a.name());
        Node.Assign b = assertInstanceOf(Node.Assign.class, a.value());
        assertEquals("b", b.name());
        assertEquals(new BigDecimal(5), ((Node.Literal) b.value()).value());
    }

    @Test
    void assignment_valueIsAWholeExpression() {
        assertEquals("(x := (d at:put: 1 (2 + 3)))", tree("x := d at: 1 put: 2 + 3"));
    }

    @Test
    void assignment_insideParenthesesIsAnOperand() {
        assertEquals("((x := 3) + 1)", tree("(x := 3) + 1"));
    }

    @Test
    void assignment_gluedWithoutSpaces() {
        assertEquals("(x := 1)", tree("x:=1"));
    }

    @Test
    void assignmentToAPath_isAnError() {
        SyntaxError error = oneError("a/b := 3");
        assertEquals(at(1, 1), error.pos());
        assertEquals("cannot assign to a path 'a/b'", error.message());
    }

    @Test
    void assignmentToAnAbsolutePath_isAnError() {
        assertEquals("cannot assign to a path '/a'", oneError("/a := 3").message());
    }

    @Test
    void assignmentToALiteral_isAnError() {
        SyntaxError error = oneError("3 := 4");
        assertEquals(at(1, 3), error.pos());
        assertEquals("expected '.' or a message, found ':='", error.message());
    }

    @Test
    void assignmentWithoutAValue_isAnError() {
        assertEquals("expected an operand, found end of input", oneError("x :=").message());
    }

    @Test
    void include_isAnOrdinaryNameWhenNotFollowedByAString() {
        assertEquals("(include := 3)", tree("include := 3"));
    }

    // ---- names ----

    @Test
    void name_isOneSegmentRelativeName() {
        Node.Name name = assertInstanceOf(Node.Name.class, only("gadget"));
        assertEquals(List.of("gadget"), name.segments());
        assertFalse(name.absolute());
    }

    @Test
    void path_isSplitIntoSegments() {
        Node.Name name = assertInstanceOf(Node.Name.class, only("root/event/alarm"));
        assertEquals("root/event/alarm", name.text());
        assertEquals(List.of("root", "event", "alarm"), name.segments());
        assertFalse(name.absolute());
    }

    @Test
    void leadingSlashPath_isAbsolute() {
        Node.Name name = assertInstanceOf(Node.Name.class, only("/event/newUAV"));
        assertEquals(List.of("event", "newUAV"), name.segments());
        assertTrue(name.absolute());
    }

    @Test
    void leadingSlashPath_asAKeywordArgument() {
        assertEquals("(p event: /event/alarm)", tree("p event: /event/alarm"));
    }

    @Test
    void division_isABinaryMessage() {
        assertEquals("(a / b)", tree("a /b"));
    }

    // ---- arrays ----

    @Test
    void array_elementsAreOperands() {
        assertEquals("#(1 \"s\" true x a/b #(2) [3] (4 + 5))", tree("#(1 \"s\" true x a/b #(2) [3] (4 + 5))"));
    }

    @Test
    void array_namesSideBySideAreElementsNotUnaryMessages() {
        Node.ArrayLiteral array = assertInstanceOf(Node.ArrayLiteral.class, only("#(a b)"));
        assertEquals(2, array.elements().size());
    }

    @Test
    void array_emptyIsAllowed() {
        assertEquals("#()", tree("#()"));
    }

    @Test
    void array_positionIsItsOpeningToken() {
        assertEquals(at(1, 3), assertInstanceOf(Node.ArrayLiteral.class, only("  #(1)")).pos());
    }

    @Test
    void array_withABinaryMessageInside_isAnError() {
        SyntaxError error = oneError("#(1 + 2)");
        assertEquals(at(1, 5), error.pos());
        assertEquals("expected an operand or ')', found '+'", error.message());
    }

    @Test
    void array_withAParenthesisedMessageInside_isAccepted() {
        assertEquals("#((1 + 2))", tree("#((1 + 2))"));
    }

    @Test
    void array_unclosed_isAnError() {
        assertEquals("expected an operand or ')', found end of input", oneError("#(1 2").message());
    }

    // ---- blocks ----

    @Test
    void block_parametersAndStatements() {
        Node.BlockLiteral block = assertInstanceOf(Node.BlockLiteral.class, only("[:x :y | x + y. x]"));
        assertEquals(List.of("x", "y"), block.params());
        assertEquals(2, block.statements().size());
        assertEquals(at(1, 1), block.pos());
    }

    @Test
    void block_trailingDotIsAllowed() {
        assertEquals("[1. 2]", tree("[1. 2.]"));
    }

    @Test
    void block_withoutParameters() {
        assertEquals("[(x foo)]", tree("[x foo]"));
    }

    @Test
    void block_empty_isAnError() {
        SyntaxError error = oneError("[]");
        assertEquals(at(1, 2), error.pos());
        assertEquals("empty block: a block needs at least one statement", error.message());
    }

    @Test
    void block_withParametersButNoStatements_isAnError() {
        SyntaxError error = oneError("[:x | ]");
        assertEquals(at(1, 7), error.pos());
        assertTrue(error.message().startsWith("empty block"), error.message());
    }

    @Test
    void block_parametersWithoutBar_isAnError() {
        SyntaxError error = oneError("[:x]");
        assertEquals(at(1, 4), error.pos());
        assertEquals("expected '|' after the block parameters, found ']'", error.message());
    }

    @Test
    void block_statementsWithoutDot_isAnError() {
        SyntaxError error = oneError("[1 2]");
        assertEquals(at(1, 4), error.pos());
        assertEquals("expected '.' or ']', found '2'", error.message());
    }

    @Test
    void block_twoDotsInARow_isAnError() {
        SyntaxError first = errors("[1..2]").get(0);
        assertEquals(at(1, 4), first.pos());
        assertEquals("expected an operand, found '.'", first.message());
    }

    // ---- statements ----

    @Test
    void emptyUnit_hasNoStatementsAndNoErrors() {
        assertEquals(List.of(), statements(""));
        assertEquals(List.of(), statements("  // nothing\n"));
    }

    @Test
    void statements_areSeparatedByDotsAndMayEndWithOne() {
        assertEquals(3, statements("1. 2. 3.").size());
    }

    @Test
    void twoDotsInARow_isAnErrorAtTheSecondDot() {
        Unit unit = parse("1.. 2");
        assertEquals(List.of(new SyntaxError(at(1, 3), "expected an operand, found '.'")), unit.errors());
        assertEquals(2, unit.statements().size(), "both statements still parse");
    }

    @Test
    void missingDotBetweenStatements_isAnError() {
        assertEquals(new SyntaxError(at(1, 3), "expected '.' or a message, found '2'"), oneError("1 2"));
    }

    @Test
    void numberThenGluedNegativeNumber_isAnError() {
        assertEquals(new SyntaxError(at(1, 3), "expected '.' or a message, found '-2'"), oneError("3 -2"));
    }

    @Test
    void nameThenGluedNegativeNumber_isAnError() {
        assertEquals(new SyntaxError(at(1, 2), "expected '.' or a message, found '-1'"), oneError("x-1"));
    }

    @Test
    void binaryOperatorThenNegativeNumber_isAccepted() {
        assertEquals("(5 + -3)", tree("5 + -3"));
    }

    @Test
    void unmatchedClosingParenthesis_isAnError() {
        assertEquals(new SyntaxError(at(1, 1), "expected an operand, found ')'"), oneError(")"));
    }

    @Test
    void unclosedParenthesis_isAnError() {
        assertEquals("expected ')', found end of input", oneError("(1 + 2").message());
    }

    @Test
    void lexicalErrors_areErrorsOfTheUnit() {
        Unit unit = parse("x := $");
        assertTrue(unit.hasErrors());
        assertEquals(new SyntaxError(at(1, 6), "unexpected character '$'"), unit.errors().get(0));
    }

    // ---- recovery ----

    @Test
    void recovery_reportsEveryBadStatementAndKeepsTheGoodOnes() {
        Unit unit = parse("""
                a := 1.
                b := ).
                c := 2.
                d := #(1 + 2).
                e := 3.
                [].
                f := 4
                """);
        assertEquals(List.of(
                new SyntaxError(at(2, 6), "expected an operand, found ')'"),
                new SyntaxError(at(4, 10), "expected an operand or ')', found '+'"),
                new SyntaxError(at(6, 2), "empty block: a block needs at least one statement")), unit.errors());
        assertEquals(List.of("(a := 1)", "(c := 2)", "(e := 3)", "(f := 4)"),
                unit.statements().stream().map(ParserTest::show).toList());
    }

    @Test
    void recovery_skipsDotsInsideBracketsOfTheBadStatement() {
        Unit unit = parse("x := (1 + ) [2. 3]. y := 5.");
        assertEquals(1, unit.errors().size(), unit.errors().toString());
        assertEquals(List.of("(y := 5)"), unit.statements().stream().map(ParserTest::show).toList());
    }

    @Test
    void recovery_anErrorInsideABlockIsReportedOnce() {
        Unit unit = parse("x := [1..2].\ny := 3.");
        assertEquals(List.of(new SyntaxError(at(1, 9), "expected an operand, found '.'")), unit.errors());
        assertEquals(List.of("(y := 3)"), unit.statements().stream().map(ParserTest::show).toList());
    }

    @Test
    void recovery_anErrorInsideParenthesesIsReportedOnce() {
        Unit unit = parse("x := (1 + . 2).\ny := 3.");
        assertEquals(List.of(new SyntaxError(at(1, 11), "expected an operand, found '.'")), unit.errors());
        assertEquals(List.of("(y := 3)"), unit.statements().stream().map(ParserTest::show).toList());
    }

    /** Lexical and parse errors are listed in the order of their places in the file. */
    @Test
    void errors_areListedInTheOrderOfTheirPlaces() {
        List<SyntaxError> errors = errors("x := 1 2.\ny := $.\nz := (3.\nw := 99r1.\n");
        assertEquals(List.of(at(1, 8), at(2, 6), at(2, 7), at(3, 8), at(4, 6)), errors.stream().map(SyntaxError::pos).toList(),
                errors.toString());
    }

    @Test
    void errors_areCappedAtOneHundredWithAFinalLine() {
        String text = ").".repeat(150);
        List<SyntaxError> errors = errors(text);
        assertEquals(Parser.MAX_ERRORS + 1, errors.size());
        for (int i = 0; i < Parser.MAX_ERRORS; i++) {
            assertEquals(new SyntaxError(at(1, 1 + 2 * i), "expected an operand, found ')'"), errors.get(i));
        }
        assertTrue(errors.get(Parser.MAX_ERRORS).message().startsWith("too many syntax errors"),
                errors.get(Parser.MAX_ERRORS).message());
    }

    @Test
    void errors_fromTheLexerAreCappedToo() {
        List<SyntaxError> errors = errors("$".repeat(10_000));
        assertEquals(Parser.MAX_ERRORS + 1, errors.size());
        assertTrue(errors.get(Parser.MAX_ERRORS).message().startsWith("too many syntax errors"));
    }

    // ---- nesting limit ----

    private static void assertNestingLimit(String text) {
        List<SyntaxError> errors = errors(text);
        assertEquals(List.of("nesting deeper than 256 levels"), errors.stream().map(SyntaxError::message).toList());
        assertEquals(1, errors.get(0).pos().line());
    }

    @Test
    void nesting_tenThousandParentheses_isOneErrorNotAStackOverflow() {
        assertNestingLimit("(".repeat(10_000) + "1" + ")".repeat(10_000));
    }

    @Test
    void nesting_tenThousandBlocks_isOneErrorNotAStackOverflow() {
        assertNestingLimit("[".repeat(10_000) + "1" + "]".repeat(10_000));
    }

    @Test
    void nesting_tenThousandArrays_isOneErrorNotAStackOverflow() {
        assertNestingLimit("#(".repeat(10_000) + "1" + ")".repeat(10_000));
    }

    @Test
    void nesting_tenThousandAssignments_isOneErrorNotAStackOverflow() {
        assertNestingLimit("a := ".repeat(10_000) + "1");
    }

    @Test
    void nesting_unclosedOpeningsOnly_isOneError() {
        assertNestingLimit("(".repeat(10_000));
    }

    @Test
    void nesting_wellBelowTheLimit_isAccepted() {
        statements("(".repeat(100) + "1" + ")".repeat(100));
        statements("[".repeat(100) + "1" + "]".repeat(100));
        statements("#(".repeat(200) + "1" + ")".repeat(200));
        statements("a := ".repeat(200) + "1");
    }

    // ---- immutability ----

    @Test
    void unit_listsCannotBeModified() {
        Unit unit = parse("1. )");
        assertThrows(UnsupportedOperationException.class, () -> unit.statements().clear());
        assertThrows(UnsupportedOperationException.class, () -> unit.errors().clear());
    }

    @Test
    void arrayNode_elementsCannotBeModified() {
        Node.ArrayLiteral array = (Node.ArrayLiteral) only("#(1 2)");
        assertThrows(UnsupportedOperationException.class, () -> array.elements().add(array));
    }

    @Test
    void blockNode_paramsAndStatementsCannotBeModified() {
        Node.BlockLiteral block = (Node.BlockLiteral) only("[:x | x]");
        assertThrows(UnsupportedOperationException.class, () -> block.params().add("y"));
        assertThrows(UnsupportedOperationException.class, () -> block.statements().remove(0));
    }

    @Test
    void messageNode_argsCannotBeModified() {
        Node.Send send = (Node.Send) only("d at: 1 put: 2");
        assertThrows(UnsupportedOperationException.class, () -> send.message().args().clear());
    }

    @Test
    void nameNode_segmentsCannotBeModified() {
        Node.Name name = (Node.Name) only("root/a/b");
        assertThrows(UnsupportedOperationException.class, () -> name.segments().set(0, "x"));
    }

    @Test
    void cascadeNode_chainsAndTheirMessagesCannotBeModified() {
        Node.Cascade cascade = (Node.Cascade) only("x a; b; c");
        assertThrows(UnsupportedOperationException.class, () -> cascade.chains().remove(0));
        assertThrows(UnsupportedOperationException.class, () -> cascade.chains().get(0).clear());
    }

    @Test
    void nodes_copyTheListsTheyAreGiven() {
        List<Node> elements = new ArrayList<>(List.of(new Node.Literal(at(1, 1), BigDecimal.ONE)));
        Node.ArrayLiteral array = new Node.ArrayLiteral(at(1, 1), elements);
        elements.clear();
        assertEquals(1, array.elements().size());
    }

    // ---- includes ----

    private static IncludeResolver files(Map<String, String> byName) {
        return (name, from) -> byName.containsKey(name) ? new IncludeResolver.Included(name, byName.get(name)) : null;
    }

    @Test
    void include_splicesTheIncludedStatementsInPlace() {
        Unit unit = Parser.parse("main.p2", "a := 1.\ninclude \"lib.p2\".\nz := 9",
                files(Map.of("lib.p2", "b := 2.\nc := 3")));
        assertEquals(List.of(), unit.errors());
        assertEquals(List.of("(a := 1)", "(b := 2)", "(c := 3)", "(z := 9)"),
                unit.statements().stream().map(ParserTest::show).toList());
        assertEquals(new SourcePos("lib.p2", 2, 1), unit.statements().get(2).pos());
    }

    @Test
    void include_resolverIsAskedWithTheIncludingSource() {
        List<String> asked = new ArrayList<>();
        IncludeResolver resolver = (name, from) -> {
            asked.add(from + "->" + name);
            return name.equals("a.p2") ? new IncludeResolver.Included("a.p2", "include \"b.p2\"")
                    : new IncludeResolver.Included("b.p2", "1");
        };
        Unit unit = Parser.parse("main.p2", "include \"a.p2\"", resolver);
        assertEquals(List.of(), unit.errors());
        assertEquals(List.of("main.p2->a.p2", "a.p2->b.p2"), asked);
        assertEquals(1, unit.statements().size());
    }

    @Test
    void include_ofAMissingFile_isAnErrorAtTheFileName() {
        Unit unit = Parser.parse("main.p2", "x := 1.\ninclude \"x.p2\".\ny := 2", files(Map.of()));
        assertEquals(List.of(new SyntaxError(new SourcePos("main.p2", 2, 9), "cannot read 'x.p2': file not found")),
                unit.errors());
        assertEquals(2, unit.statements().size(), "the other statements still parse");
    }

    @Test
    void include_unreadableFile_isAnErrorNamingTheCause() {
        IncludeResolver broken = (name, from) -> {
            throw new UncheckedIOException(new IOException("disk on fire"));
        };
        Unit unit = Parser.parse("main.p2", "include \"x.p2\"", broken);
        assertEquals(List.of(new SyntaxError(new SourcePos("main.p2", 1, 9), "cannot read 'x.p2': disk on fire")),
                unit.errors());
    }

    @Test
    void include_syntaxErrorsOfTheIncludedFileNameThatFile() {
        Unit unit = Parser.parse("main.p2", "include \"lib.p2\"", files(Map.of("lib.p2", "\n  )")));
        assertEquals(List.of(new SyntaxError(new SourcePos("lib.p2", 2, 3), "expected an operand, found ')'")),
                unit.errors());
    }

    @Test
    void include_ofItself_stopsAtTheDepthLimitWithOneError() {
        Unit unit = Parser.parse("self.p2", "include \"self.p2\".\nx := 1",
                files(Map.of("self.p2", "include \"self.p2\".\nx := 1")));
        assertEquals(1, unit.errors().size(), unit.errors().toString());
        SyntaxError error = unit.errors().get(0);
        assertEquals(new SourcePos("self.p2", 1, 9), error.pos());
        assertEquals("include nested deeper than 16 levels (does a file include itself?)", error.message());
    }

    @Test
    void include_withoutAResolver_isAnError() {
        assertEquals("cannot read 'lib.p2': file not found", oneError("include \"lib.p2\"").message());
    }

    @Test
    void include_mustBeFollowedByADot() {
        Unit unit = Parser.parse("main.p2", "include \"a.p2\" 3", files(Map.of("a.p2", "1")));
        assertEquals(List.of(new SyntaxError(new SourcePos("main.p2", 1, 16), "expected '.' or a message, found '3'")),
                unit.errors());
    }

    @Test
    void eachStatement_isHandedOnAsSoonAsItIsParsed_beforeTheRestIsRead() {
        List<String> seen = new ArrayList<>();
        List<SyntaxError> errors = Parser.parse(SOURCE, "a := 1.\nb := 2.\nc $ d", IncludeResolver.NONE,
                statement -> seen.add(show(statement) + " with " + seen.size() + " before"));

        assertEquals(List.of("(a := 1) with 0 before", "(b := 2) with 1 before"), seen.subList(0, 2));
        assertEquals(1, errors.size(), "the '$' is found after the first statements were handed on: " + errors);
    }

    @Test
    void aCheckedUnit_keepsItsText_andGivesItsStatementsAgainOneByOne() {
        Unit unit = parse("a := 1. b := a + 1. c");
        List<String> shown = new ArrayList<>();

        unit.forEachStatement(statement -> shown.add(show(statement)));

        assertEquals(List.of("(a := 1)", "(b := (a + 1))", "c"), shown);
        assertEquals(shown, unit.statements().stream().map(ParserTest::show).toList());
    }

    @Test
    void anIncludedFile_isReadOnce_evenWhenTheStatementsAreGivenAgain() {
        int[] reads = {0};
        IncludeResolver counting = (name, from) -> {
            reads[0]++;
            return new IncludeResolver.Included(name, "x := " + reads[0] + ".");
        };
        Unit unit = Parser.parse(SOURCE, "include \"a.p2\". y", counting);

        assertEquals(List.of("(x := 1)", "y"), unit.statements().stream().map(ParserTest::show).toList());
        assertEquals(List.of("(x := 1)", "y"), unit.statements().stream().map(ParserTest::show).toList());
        assertEquals(1, reads[0]);
    }
}
