package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ShellCommandTest {
    @TempDir
    Path dir;

    private Smc smc;

    @BeforeEach
    void setUp() {
        smc = Smc.in(dir);
    }

    @Test
    void shell_printsTheValueOfEachInput_andVariablesPersist() {
        Smc.Result result = smc.withInput("x := 5.\nx + 1.\n\"a\" + \"b\".\n", "shell");

        assertEquals(List.of("5", "6", "ab"), result.outLines());
        assertEquals("", result.err());
        assertEquals(0, result.status());
    }

    @Test
    void rootPrint_printsItsLine_thenTheValue() {
        Smc.Result result = smc.withInput("root print: 3 + 4.\n", "shell");

        assertEquals(List.of("7", "7"), result.outLines());
    }

    @Test
    void error_isPrintedOnStderr_andTheShellGoesOn() {
        Smc.Result result = smc.withInput("x := 2.\nroot frob.\nx * 10.\n", "shell");

        assertEquals(List.of("stdin:1:6: unknown operation 'frob' on SelfManagedCell"), result.errLines());
        assertEquals(List.of("2", "20"), result.outLines());
        assertEquals(0, result.status());
    }

    /**
     * A line that is not UTF-8 is reported, naming its line and byte, and the input it belongs to is
     * skipped whole (run without that line it would be another statement); the shell goes on.
     */
    @Test
    void aLineThatIsNotUtf8_isReported_andItsInputSkipped() {
        byte[] input = "x := 2.\nx := 10\n  * \u00ff\n  + 1.\nx * 10.\n".getBytes(java.nio.charset.StandardCharsets.ISO_8859_1);

        Smc.Result result = smc.withInputBytes(input, "shell");

        assertEquals(List.of("stdin:3: not valid UTF-8: byte 0xFF at byte 5 of the line; the shell reads UTF-8, and skips "
                + "the input the line belongs to"), result.errLines());
        assertEquals(List.of("2", "20"), result.outLines(), "x stays 2: 'x := 10 + 1' did not run");
        assertEquals(0, result.status());
    }

    @Test
    void input_spansLinesUntilOneEndsInADot() {
        Smc.Result result = smc.withInput("y := 3\n  * 4\n  + 1.   \n\n\ny.\n", "shell");

        assertEquals(List.of("13", "13"), result.outLines());
        assertEquals("", result.err());
    }

    @Test
    void errorLines_countFromTheStartOfEachInput() {
        Smc.Result result = smc.withInput("1 + 1.\nx := 1\n  frob.\n", "shell");

        assertEquals(List.of("stdin:2:3: unknown operation 'frob' on Number"), result.errLines());
    }

    @Test
    void textLeftWithoutAFinalDot_runsAtTheEnd() {
        Smc.Result result = smc.withInput("x := 4.\nx * x", "shell");

        assertEquals(List.of("4", "16"), result.outLines());
    }

    @Test
    void lineEndingInADotInsideAString_stillEndsTheInput() {
        Smc.Result result = smc.withInput("\"a.\nb\".\n", "shell");

        assertEquals(List.of(), result.outLines());
        assertEquals(2, result.errLines().size(), result.err());
    }

    @Test
    void bootFiles_runFirst_andTheirDefinitionsAreVisible() {
        String boot = smc.file("boot.p2", "root at: \"d\" put: (root/factory/domain create).\nroot print: \"booted\".\n");

        Smc.Result result = smc.withInput("root/d class.\n", "shell", boot);

        assertEquals(List.of("booted", "Domain"), result.outLines());
    }

    @Test
    void authDeny_failsAPolicyActionAfterBoot_whileTheBootUnitWasAllowed() {
        String boot = smc.file("boot.p2", """
                root/event at: "go" put: (root/factory/event create: #("v")).
                root at: "d" put: (root/factory/domain create).
                p := root/factory/ecapolicy create. root/policy at: "p" put: p.
                p event: root/event/go; action: [:v | root/d at: "k" put: v].
                p active: true.
                root/event/go create: #(0).
                """);

        Smc.Result result = smc.withInput("root/event/go create: #(1).\nroot/d at: \"k\".\n", "shell", "--auth", "deny", boot);

        assertEquals(List.of(boot + ":4:46: ObligationPolicy: unhandled action error: Ponder2AuthorizationException: at:put:"),
                result.errLines());
        assertEquals(List.of("<EventTemplate root/event/go>", "0"), result.outLines(), "the boot raise set k; the later one did not");
        assertEquals(0, result.status());
    }

    @Test
    void authAllow_letsThePolicyActionRunAfterBoot() {
        String boot = smc.file("boot.p2", """
                root/event at: "go" put: (root/factory/event create: #("v")).
                root at: "d" put: (root/factory/domain create).
                p := root/factory/ecapolicy create. root/policy at: "p" put: p.
                p event: root/event/go; action: [:v | root/d at: "k" put: v].
                p active: true.
                """);

        Smc.Result result = smc.withInput("root/event/go create: #(1).\nroot/d at: \"k\".\n", "shell", "--auth", "allow", boot);

        assertEquals("", result.err());
        assertEquals(List.of("<EventTemplate root/event/go>", "1"), result.outLines());
    }

    @Test
    void rootExit_endsTheShellWithItsStatus() {
        Smc.Result result = smc.withInput("root print: 1.\nroot exit: 4.\nroot print: 2.\n", "shell");

        assertEquals(List.of("1", "1"), result.outLines());
        assertEquals(4, result.status());
    }

    @Test
    void rootExitInABootFile_endsBeforeReadingInput() {
        String boot = smc.file("boot.p2", "root exit: 5.\n");

        Smc.Result result = smc.withInput("root print: 1.\n", "shell", boot);

        assertEquals("", result.out());
        assertEquals(5, result.status());
    }

    @Test
    void errorsInBootFiles_areReported_butTheShellEndsWith0() {
        String boot = smc.file("boot.p2", "root frob.\n");

        Smc.Result result = smc.withInput("1 + 1.\n", "shell", boot);

        assertEquals(List.of(boot + ":1:6: unknown operation 'frob' on SelfManagedCell"), result.errLines());
        assertEquals(List.of("2"), result.outLines());
        assertEquals(0, result.status());
    }

    @Test
    void onATerminal_promptsForFirstAndContinuationLines() {
        Smc.Result result = smc.onTerminal().withInput("x := 1\n + 1.\n", "shell");

        assertEquals("smc> ...> 2\nsmc> \n", result.out());
    }

    @Test
    void offATerminal_printsNoPrompt() {
        Smc.Result result = smc.withInput("x := 1\n + 1.\n", "shell");

        assertEquals("2\n", result.out());
    }
}
