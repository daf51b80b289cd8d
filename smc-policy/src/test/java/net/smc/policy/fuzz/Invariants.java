package net.smc.policy.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.api.Limits;
import net.smc.policy.RunResult;
import net.smc.policy.lang.Lexer;
import net.smc.policy.lang.Parser;
import net.smc.policy.lang.SourcePos;
import net.smc.policy.lang.SyntaxError;
import net.smc.policy.lang.Token;
import net.smc.policy.lang.TokenKind;
import net.smc.policy.lang.Unit;

/**
 * What must hold for any input text, fuzzed or generated: the lexer and parser never throw and
 * place every token and error inside the text; a cell with small limits never lets an exception
 * escape and reports errors with 1-based positions.
 */
final class Invariants {
    static final String SOURCE = "fuzz.p2";
    /** Small enough that any run ends quickly. */
    static final Limits SMALL = Limits.DEFAULT.withMaxSteps(10_000).withMaxCallDepth(100);

    private Invariants() {
    }

    /** Lexes and parses {@code text}, checking every position. */
    static Unit lexAndParse(String text) {
        Lines lines = new Lines(text);
        List<SyntaxError> lexErrors = new ArrayList<>();
        List<Token> tokens = Lexer.tokenize(SOURCE, text, lexErrors);
        assertTrue(!tokens.isEmpty() && tokens.get(tokens.size() - 1).kind() == TokenKind.EOF, "ends with EOF");
        for (int i = 0; i < tokens.size(); i++) {
            Token t = tokens.get(i);
            assertTrue(t.kind() != TokenKind.EOF || i == tokens.size() - 1, "EOF only at the end");
            int offset = lines.offsetOf(t.pos());
            assertTrue(startsAt(text, offset, t), () -> t + " is not at offset " + offset);
        }
        for (SyntaxError e : lexErrors) {
            lines.offsetOf(e.pos());
        }
        Unit unit = Parser.parse(SOURCE, text);
        assertTrue(unit.errors().size() <= Parser.MAX_ERRORS + 1, "errors are capped");
        for (SyntaxError e : unit.errors()) {
            lines.offsetOf(e.pos());
        }
        return unit;
    }

    /** Whether the token's text is where its position says (strings and parameters show their value). */
    private static boolean startsAt(String text, int offset, Token t) {
        return switch (t.kind()) {
            case EOF -> offset <= text.length();
            case STRING -> text.charAt(offset) == '"';
            case PARAM -> text.startsWith(":" + t.text(), offset);
            default -> text.startsWith(t.text(), offset);
        };
    }

    /**
     * Runs {@code text} as one unit of a fresh cell with {@link #SMALL} limits, then checks the
     * cell still runs another unit.
     *
     * @return what the cell reported
     */
    static List<Diagnostic> runInCell(String text) {
        List<Diagnostic> reported = new ArrayList<>();
        PolicyEngine cell = PolicyEngine.builder().limits(SMALL).errors(reported::add).output(line -> { }).build();
        RunResult result = cell.run(SOURCE, text);
        assertNotNull(result);
        for (Diagnostic d : reported) {
            assertNotNull(d.message(), "every diagnostic has a message");
            SourcePos pos = d.pos();
            if (pos != null) {
                assertTrue(pos.line() >= 1 && pos.column() >= 1, () -> "1-based position: " + d);
            }
        }
        if (result.status() != RunResult.Status.EXITED) {
            RunResult after = cell.run("after.p2", "1 + 1");
            assertEquals(RunResult.Status.OK, after.status(), "the cell still runs units");
            assertEquals("2", PolicyEngine.print(after.value()));
        }
        return reported;
    }

    /**
     * Line starts of a text, to turn 1-based line and column into an offset. A line ends at a line
     * feed, or at a carriage return that no line feed follows (as the lexer counts them).
     */
    private static final class Lines {
        private final String text;
        private final List<Integer> starts = new ArrayList<>();

        Lines(String text) {
            this.text = text;
            starts.add(0);
            for (int i = 0; i < text.length(); i++) {
                char c = text.charAt(i);
                if (c == '\n' || c == '\r' && (i + 1 >= text.length() || text.charAt(i + 1) != '\n')) {
                    starts.add(i + 1);
                }
            }
        }

        /** The offset of a position, which must be inside the text (or just after a line's end). */
        int offsetOf(SourcePos pos) {
            assertEquals(SOURCE, pos.source());
            assertTrue(pos.line() >= 1 && pos.line() <= starts.size(), () -> "line of " + pos + " in " + starts.size());
            int start = starts.get(pos.line() - 1);
            int end = pos.line() < starts.size() ? starts.get(pos.line()) - 1 : text.length();
            assertTrue(pos.column() >= 1 && pos.column() <= end - start + 1,
                    () -> "column of " + pos + " on a line of " + (end - start) + " characters");
            return start + pos.column() - 1;
        }
    }
}
