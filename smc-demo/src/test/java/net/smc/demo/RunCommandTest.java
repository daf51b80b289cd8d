package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RunCommandTest {
    @TempDir
    Path dir;

    private Smc smc;

    @BeforeEach
    void setUp() {
        smc = Smc.in(dir);
    }

    @Test
    void run_printsGoToStdoutOnly_andExitStatusIs0() {
        String file = smc.file("a.p2", """
                root print: 3 + 4.
                root print: "a" + "b".
                x := 5.
                """);

        Smc.Result result = smc.run("run", file);

        assertEquals(List.of("7", "ab"), result.outLines());
        assertEquals("", result.err());
        assertEquals(0, result.status());
    }

    @Test
    void run_runsFilesInOrderInOneCell() {
        String first = smc.file("first.p2", "root at: \"n\" put: (root/factory/domain create).\n");
        String second = smc.file("second.p2", "root print: root/n class.\n");

        Smc.Result result = smc.run("run", first, second);

        assertEquals(List.of("Domain"), result.outLines());
        assertEquals(0, result.status());
    }

    @Test
    void runtimeError_isFileLineColOnStderr_andExitStatusIs1() {
        String file = smc.file("bad.p2", "root print: 1.\nroot frob.\nroot print: 2.\n");

        Smc.Result result = smc.run("run", file);

        assertEquals(List.of(file + ":2:6: unknown operation 'frob' on SelfManagedCell"), result.errLines());
        assertEquals(List.of("1"), result.outLines(), "the unit stops at its first runtime error");
        assertEquals(1, result.status());
    }

    @Test
    void syntaxErrorInOneFile_laterFilesStillRun_andExitStatusIs1() {
        String broken = smc.file("broken.p2", "root print: \"never\".\nroot print: (1 +.\n");
        String later = smc.file("later.p2", "root print: \"later\".\n");

        Smc.Result result = smc.run("run", broken, later);

        assertEquals(List.of("later"), result.outLines(), "nothing of a unit with a syntax error runs");
        assertEquals(1, result.errLines().size(), result.err());
        assertTrue(result.err().startsWith(broken + ":2:17: "), result.err());
        assertEquals(1, result.status());
    }

    @Test
    void errorInsidePolicy_doesNotStopTheUnit_butExitStatusIs1() {
        String file = smc.file("policy.p2", """
                root/event at: "go" put: (root/factory/event create: #("v")).
                p := root/factory/ecapolicy create.
                p event: root/event/go; action: [:v | root frob].
                p active: true.
                root/event/go create: #(1).
                root print: "after".
                """);

        Smc.Result result = smc.run("run", file);

        assertEquals(List.of("after"), result.outLines());
        assertEquals(List.of(file + ":3:44: ObligationPolicy: unhandled action error: unknown operation 'frob' on SelfManagedCell"),
                result.errLines());
        assertEquals(1, result.status());
    }

    @Test
    void rootExit_givesItsStatus_andStopsLaterFiles() {
        String exits = smc.file("exit.p2", "root print: 1.\nroot exit: 3.\nroot print: 2.\n");
        String later = smc.file("later.p2", "root print: \"later\".\n");

        Smc.Result result = smc.run("run", exits, later);

        assertEquals(List.of("1"), result.outLines());
        assertEquals(3, result.status());
    }

    @Test
    void plainRootExit_givesStatus0_evenAfterAnError() {
        String bad = smc.file("bad.p2", "root frob.\n");
        String exits = smc.file("exit.p2", "root exit.\n");

        assertEquals(0, smc.run("run", bad, exits).status());
    }

    @Test
    void rootExitInsidePolicyAction_stopsEverything() {
        String file = smc.file("exit.p2", """
                root/event at: "go" put: (root/factory/event create: #("v")).
                p := root/factory/ecapolicy create.
                p event: root/event/go; action: [:v | root exit: v].
                p active: true.
                root/event/go create: #(7).
                root print: "after".
                """);

        Smc.Result result = smc.run("run", file);

        assertEquals("", result.out());
        assertEquals(7, result.status());
    }

    @Test
    void bootUnitsAreAllowed_underAuthDeny() {
        String file = smc.file("boot.p2", """
                root at: "d" put: (root/factory/domain create).
                p := root/factory/ecapolicy create.
                root/event at: "go" put: (root/factory/event create: #("v")).
                p event: root/event/go; action: [:v | root/d at: "k" put: v].
                p active: true.
                root/event/go create: #(1).
                root print: (root/d at: "k").
                """);

        Smc.Result result = smc.run("run", "--auth", "deny", file);

        assertEquals("", result.err());
        assertEquals(List.of("1"), result.outLines());
        assertEquals(0, result.status());
    }

    @Test
    void readAndInclude_resolveNextToTheFile() throws Exception {
        Path sub = Files.createDirectory(dir.resolve("sub"));
        Files.writeString(sub.resolve("helper.p2"), "root print: \"read\".\n");
        Files.writeString(sub.resolve("main.p2"), "root read: \"helper.p2\".\n");

        Smc.Result result = smc.run("run", "sub/main.p2");

        assertEquals("", result.err());
        assertEquals(List.of("read"), result.outLines());
    }

    @Test
    void policyUris_resolveInThePoliciesFolderOfTheCurrentDirectory() throws Exception {
        Files.createDirectories(dir.resolve("policies/roles"));
        Files.writeString(dir.resolve("policies/roles/hello.p2"), "root print: \"hello\".\n");
        String file = smc.file("main.p2", "root read: \"policy:/roles/hello\".\n");

        Smc.Result result = smc.run("run", file);

        assertEquals("", result.err());
        assertEquals(List.of("hello"), result.outLines());
    }

    @Test
    void repositoryOption_overridesThePoliciesFolder() throws Exception {
        Files.createDirectories(dir.resolve("elsewhere"));
        Files.writeString(dir.resolve("elsewhere/hello.p2"), "root print: \"elsewhere\".\n");
        String file = smc.file("main.p2", "root read: \"policy:/hello\".\n");

        Smc.Result result = smc.run("run", "--repository", "elsewhere", file);

        assertEquals("", result.err());
        assertEquals(List.of("elsewhere"), result.outLines());
    }

    @Test
    void deepRecursion_endsAtTheEnginesCallDepthLimit() {
        String file = smc.file("deep.p2", """
                d := #(0).
                d at: 0 put: [:n | n > 0 ifTrue: [(d at: 0) value: n - 1] ifFalse: [0]].
                root print: ((d at: 0) value: 300).
                (d at: 0) value: 100000.
                """);

        Smc.Result result = smc.run("run", file);

        assertEquals(List.of("0"), result.outLines());
        assertEquals(1, result.errLines().size(), result.err());
        assertTrue(result.err().contains("call depth limit"), result.err());
        assertEquals(1, result.status());
    }

    @Test
    void randomAndClock_areLive() {
        String file = smc.file("live.p2", """
                root print: ((root load: "DateTime") create secs > 0).
                root print: ((1000000 random) class).
                """);

        Smc.Result result = smc.run("run", file);

        assertEquals("", result.err());
        assertEquals(List.of("true", "Number"), result.outLines());
    }

    @Test
    void run_passesTheArgumentsAfterDashDash_toTheCell() {
        String file = smc.file("args.p2", """
                root print: root argsAsArray.
                root print: root argsAsHash.
                """);

        Smc.Result result = smc.run("run", file, "--", "-n", "3", "x");

        assertEquals(List.of("[-n, 3, x]", "{ n=\"3\" }"), result.outLines());
        assertEquals(0, result.status());
    }

    @Test
    void run_keepsGoingWhileATimerIsPending_andEndsWhenItIsCancelled() {
        String file = smc.file("ticks.p2", """
                root/event at: "tick" put: (root/factory/event create: #("count")).
                p := root/factory/ecapolicy create.
                p event: root/event/tick; action: [:count | root print: "tick " + count.
                    (count == 3) ifTrue: [root/timer cancel]].
                p active: true.
                root at: "timer" put: (root load: "Timer") create.
                root/timer repeat: 5 event: root/event/tick.
                """);

        Smc.Result result = smc.run("run", file);

        assertEquals(List.of("tick 1", "tick 2", "tick 3"), result.outLines());
        assertEquals(0, result.status());
    }
}
