package net.smc.policy.fuzz;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;
import net.smc.policy.lang.Lexer;
import net.smc.policy.lang.Parser;
import net.smc.policy.lang.SyntaxError;
import net.smc.policy.lang.Token;
import net.smc.policy.lang.TokenKind;
import net.smc.policy.lang.Unit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Hostile inputs without Jazzer: random bytes, huge literals, deep nesting, endless loops,
 * unbounded recursion and event storms. Each must end quickly with diagnostics, never with an
 * exception, and leave the cell usable.
 */
class RobustnessTest {
    /**
     * A hang guard, not a speed check: far beyond what one of these runs takes even on a loaded
     * machine, so that only a run that never ends fails here instead of stalling the build.
     */
    private static final Duration QUICK = Duration.ofSeconds(60);
    /** The hang guard for the batches of thousands of random inputs. */
    private static final Duration BATCH = Duration.ofSeconds(120);

    private final List<Diagnostic> reported = new ArrayList<>();
    private final List<String> output = new ArrayList<>();
    private final PolicyEngine cell = PolicyEngine.builder().limits(Invariants.SMALL).errors(reported::add).output(output::add).build();

    private List<String> messages() {
        return reported.stream().map(Diagnostic::message).toList();
    }

    private RunResult run(String text) {
        return bounded(() -> cell.run("t.p2", text));
    }

    /**
     * Runs {@code work} on its own thread and fails if it has not finished within {@link #QUICK}.
     * A run that hangs is then stopped, so that a spinning interpreter does not slow every later
     * test in this JVM (Thread.stop is a last resort, acceptable for a test guard on JDK 17).
     */
    private static <T> T bounded(Callable<T> work) {
        return bounded(QUICK, work);
    }

    /** Runs {@code work} on its own thread; see {@link #bounded(Callable)}. */
    @SuppressWarnings({"removal", "deprecation"})
    private static <T> T bounded(Duration limit, Callable<T> work) {
        AtomicReference<Object> outcome = new AtomicReference<>();
        Thread worker = new Thread(null, () -> {
            try {
                outcome.set(new Object[] {work.call()});
            } catch (Throwable e) {
                outcome.set(e);
            }
        }, "bounded-run", 0);
        worker.setDaemon(true);
        worker.start();
        try {
            worker.join(limit.toMillis());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError("interrupted", e);
        }
        if (worker.isAlive()) {
            try {
                worker.stop();
            } catch (UnsupportedOperationException ignored) {
                // Newer JDKs cannot stop threads; the daemon thread is left to the JVM's exit.
            }
            fail("did not finish within " + limit.toSeconds() + " s: the run hangs");
        }
        Object result = outcome.get();
        if (result instanceof Error e) {
            throw e;
        }
        if (result instanceof Throwable t) {
            throw new AssertionError("the run threw " + t, t);
        }
        @SuppressWarnings("unchecked")
        T value = (T) ((Object[]) result)[0];
        return value;
    }

    private void assertCellStillWorks() {
        reported.clear();
        output.clear();
        assertEquals(RunResult.Status.OK, run("root print: 1 + 1").status());
        assertEquals(List.of("2"), output);
        assertEquals(List.of(), reported);
    }

    // ---- random input ----

    private static Void randomBytes(Charset charset, long seed) {
        Random random = new Random(seed);
        for (int i = 0; i < 2_000; i++) {
            byte[] bytes = new byte[random.nextInt(200)];
            random.nextBytes(bytes);
            String text = new String(bytes, charset);
            Invariants.lexAndParse(text);
            Invariants.runInCell(text);
        }
        return null;
    }

    @Test
    void randomBytes_asIso88591_neverThrow() {
        bounded(BATCH, () -> randomBytes(StandardCharsets.ISO_8859_1, 1));
    }

    @Test
    void randomBytes_asUtf8_neverThrow() {
        bounded(BATCH, () -> randomBytes(StandardCharsets.UTF_8, 2));
    }

    /** Pieces of PonderTalk, so that random texts get past the lexer and often the parser. */
    private static final String[] PIECES = {
        "root", "x", "y", ":=", " ", ".", ";", "(", ")", "[", "]", "#(", ":a", "|", "+", "-", "/", "==", "<",
        "1", "-2", "3.5", "1e3", "16rFF", "\"s\"", "\"", "true", "false", "print:", "at:", "put:", "value",
        "value:", "size", "class", "root/event", "/event", "root/factory/domain", "create", "ifTrue:", "not",
        "add:", "asHash", "readString:", "\n", "//c\n", "$", "include", "onError:", "self",
    };

    @Test
    void randomTokenSoup_neverThrows() {
        bounded(BATCH, () -> {
            Random random = new Random(3);
            for (int i = 0; i < 2_000; i++) {
                StringBuilder text = new StringBuilder();
                int n = random.nextInt(40);
                for (int j = 0; j < n; j++) {
                    text.append(PIECES[random.nextInt(PIECES.length)]).append(random.nextInt(3) == 0 ? "" : " ");
                }
                Invariants.lexAndParse(text.toString());
                Invariants.runInCell(text.toString());
            }
            return null;
        });
    }

    // ---- size ----

    @Test
    void tenMegabyteStringLiteral_roundTripsItsLength() {
        int length = 10 * 1024 * 1024;
        PolicyEngine.Session session = cell.session();
        RunResult result = bounded(
                () -> session.run("big.p2", "x := \"" + "a".repeat(length) + "\"."));
        assertEquals(RunResult.Status.OK, result.status(), messages().toString());
        assertEquals(length, ((String) session.variable("x")).length());
    }

    @Test
    void tenMegabyteStringLiteral_isOneToken() {
        int length = 10 * 1024 * 1024;
        List<SyntaxError> errors = new ArrayList<>();
        List<Token> tokens = Lexer.tokenize("big.p2", "\"" + "a".repeat(length) + "\"", errors);
        assertEquals(List.of(), errors);
        assertEquals(TokenKind.STRING, tokens.get(0).kind());
        assertEquals(length, ((String) tokens.get(0).value()).length());
    }

    @Test
    void millionCharacterLineOfPlus_isOneSyntaxError() {
        RunResult result = run("+".repeat(1_000_000));
        assertEquals(RunResult.Status.SYNTAX_ERROR, result.status());
        assertEquals(1, reported.size(), messages().toString());
        assertTrue(messages().get(0).startsWith("expected an operand, found '+++"), messages().get(0));
        assertTrue(messages().get(0).length() < 100, "the token is abbreviated: " + messages().get(0));
    }

    /** Runs a long flat chain of sends, which the parser accepts without any nesting. */
    private RunResult runChain(String text) {
        PolicyEngine fresh = PolicyEngine.builder().errors(reported::add).build();
        return bounded(() -> assertDoesNotThrow(() -> fresh.run("chain.p2", text),
                "PolicyEngine.run must report, not throw, for a chain of " + text.length() + " characters"));
    }

    @Test
    void millionCharacterBinaryChain_runsOrFailsWithADiagnostic() {
        RunResult result = runChain("1" + " + 1".repeat(250_000));
        assertTrue(result.ok() || !reported.isEmpty(), "either a value or a reported error");
        if (result.ok()) {
            assertEquals("250001", PolicyEngine.print(result.value()));
        }
    }

    @Test
    void longUnaryChain_runsOrFailsWithADiagnostic() {
        RunResult result = runChain("1" + " self".repeat(200_000));
        assertTrue(result.ok() || !reported.isEmpty(), "either a value or a reported error");
    }

    @ParameterizedTest
    @ValueSource(strings = {"9", "0x", "36r"})
    void millionDigitNumberLiteral_isLexedQuickly(String prefix) {
        String digit = switch (prefix) {
            case "0x" -> "f";
            case "36r" -> "Z";
            default -> "9";
        };
        String text = prefix + digit.repeat(1_000_000);
        List<SyntaxError> errors = new ArrayList<>();
        List<Token> tokens = bounded(() -> Lexer.tokenize("n.p2", text, errors));
        assertTrue(tokens.get(0).kind() == TokenKind.NUMBER || !errors.isEmpty(), "a number or an error");
    }

    @Test
    void includeOfANameWithANulCharacter_isASyntaxErrorNotAnException() {
        RunResult result = bounded(() -> assertDoesNotThrow(() -> cell.run("t.p2", "include \"a\u0000b\"")));
        assertEquals(RunResult.Status.SYNTAX_ERROR, result.status());
        assertEquals(1, reported.size(), messages().toString());
        assertTrue(messages().get(0).startsWith("cannot read 'a"), messages().get(0));
    }

    @Test
    void readOfANameWithANulCharacter_isARuntimeErrorNotAnException() {
        RunResult result = bounded(() -> assertDoesNotThrow(() -> cell.run("t.p2", "root read: \"a\u0000b\"")));
        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status());
        assertEquals(1, reported.size(), messages().toString());
    }

    // ---- nesting ----

    @ParameterizedTest
    @ValueSource(strings = {"(", "[", "#(", "a := "})
    void tenThousandDeepNesting_isOneSyntaxErrorNamingTheLimit(String opening) {
        String closing = switch (opening) {
            case "(", "#(" -> ")";
            case "[" -> "]";
            default -> "";
        };
        RunResult result = run(opening.repeat(10_000) + "1" + closing.repeat(10_000));
        assertEquals(RunResult.Status.SYNTAX_ERROR, result.status());
        assertEquals(List.of("nesting deeper than 256 levels"), messages());
        assertCellStillWorks();
    }

    @Test
    void deepNesting_isParsedWithoutStackOverflowByTheParserAlone() {
        Unit unit = bounded(
                () -> Parser.parse("deep.p2", "(".repeat(100_000) + "1" + ")".repeat(100_000)));
        assertEquals(1, unit.errors().size());
    }

    // ---- loops, recursion, storms ----

    @Test
    void endlessLoop_withSendsInItsBody_stopsAtTheStepLimit() {
        RunResult result = run("[true] whileTrue: [1 + 1]");
        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status());
        assertEquals(List.of("step limit of 10000 sends exceeded"), messages());
        assertCellStillWorks();
    }

    @Test
    void endlessLoop_withoutSendsInItsBody_stopsAtTheStepLimit() {
        RunResult result = run("[true] whileTrue: [1]");
        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status());
        assertEquals(List.of("step limit of 10000 sends exceeded"), messages());
        assertCellStillWorks();
    }

    @Test
    void hugeCountedLoop_withoutSendsInItsBody_stopsAtTheStepLimit() {
        RunResult result = run("1000000000000 do: [:i | i]");
        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status());
        assertEquals(List.of("step limit of 10000 sends exceeded"), messages());
    }

    @Test
    void unboundedRecursionThroughADomain_stopsAtTheCallDepthLimit() {
        RunResult result = run("""
                h := root/factory/domain create.
                h at: "f" put: [:n | (h at: "f") value: n + 1].
                (h at: "f") value: 0.
                root print: "not reached"
                """);
        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status());
        assertEquals(List.of("call depth limit of 100 exceeded"), messages());
        assertEquals(List.of(), output);
        assertCellStillWorks();
    }

    @Test
    void unboundedRecursionThroughAHash_stopsAtTheCallDepthLimit() {
        run("h := #() asHash. h at: \"f\" put: [:n | (h at: \"f\") value: n + 1]. (h at: \"f\") value: 0");
        assertEquals(List.of("call depth limit of 100 exceeded"), messages());
    }

    @Test
    void eventStorm_endsWithOneActionErrorAndTheCellStillWorks() {
        RunResult result = run("""
                root/event at: "e" put: (root/factory/event create: #("n")).
                p := root/factory/ecapolicy create.
                root/policy at: "storm" put: p.
                p event: root/event/e; action: [:n | root/event/e create: #((n + 1))].
                p active: true.
                root/event/e create: #(0).
                root print: "raised"
                """);
        assertEquals(RunResult.Status.OK, result.status(), "policy errors never reach the raising script");
        assertEquals(List.of("raised"), output);
        assertEquals(List.of("ObligationPolicy: unhandled action error: call depth limit of 100 exceeded"), messages());
        assertCellStillWorks();
    }

    @Test
    void eventStorm_raisedFromJava_endsWithOneActionError() {
        run("""
                root/event at: "e" put: (root/factory/event create: #("n")).
                p := root/factory/ecapolicy create.
                root/policy at: "storm" put: p.
                p event: root/event/e; action: [:n | root/event/e create: #((n + 1))].
                p active: true.
                """);
        reported.clear();
        bounded(() -> cell.raise("root/event/e", 0));
        assertEquals(List.of("ObligationPolicy: unhandled action error: call depth limit of 100 exceeded"), messages());
        assertCellStillWorks();
    }

    @Test
    void stepLimit_isPerRun() {
        run("[true] whileTrue: [1 + 1]");
        assertCellStillWorks();
        reported.clear();
        RunResult result = run("c := #(0). 1000 do: [:i | c at: 0 put: (c at: 0) + 1]. c at: 0");
        assertEquals(RunResult.Status.OK, result.status(), messages().toString());
        assertEquals("1000", PolicyEngine.print(result.value()));
    }

    @Test
    void arrayContainingItself_printsOrFailsWithADiagnostic() {
        RunResult result = run("a := #(). a add: a. root print: a");
        assertTrue(result.ok() || !reported.isEmpty(), "either printed or reported");
        assertCellStillWorks();
    }
}
