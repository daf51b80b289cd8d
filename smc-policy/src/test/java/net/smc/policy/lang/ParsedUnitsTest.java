package net.smc.policy.lang;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import net.smc.policy.PolicyEngine;
import net.smc.policy.RunResult;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The parse shared by the cells of one process: kept only when safe, and running the same statements. */
class ParsedUnitsTest {
    private static final String TEXT = "a := 3.\nroot print: a + 4.\nroot print: \"done\"";

    @Test
    void aCleanUnit_isKeptWithTheSameStatements() {
        ParsedUnits shared = new ParsedUnits(8, 1_000);
        assertNull(shared.find("t.p2", TEXT));
        Unit checked = Parser.parse("t.p2", TEXT);
        Unit kept = shared.keep(checked, TEXT, false);
        assertEquals(checked.statements(), kept.statements());
        assertSame(kept, shared.find("t.p2", TEXT));
        assertNull(shared.find("u.p2", TEXT), "another source's unit is another unit");
        assertNull(shared.find("t.p2", TEXT + "."), "another text is another unit");
    }

    @Test
    void unitsWithErrorsIncludesOrLongText_areNotKept() {
        ParsedUnits shared = new ParsedUnits(8, 20);
        String broken = "a := (";
        Unit withErrors = Parser.parse("t.p2", broken);
        assertSame(withErrors, shared.keep(withErrors, broken, false));
        assertNull(shared.find("t.p2", broken));
        String small = "a := 1";
        Unit includer = Parser.parse("t.p2", small);
        assertSame(includer, shared.keep(includer, small, true));
        assertNull(shared.find("t.p2", small), "a unit that included a file is not kept");
        assertEquals(0, shared.size());
        String longText = "a := 1. b := 2. c := 3. d := 4";
        shared.keep(Parser.parse("t.p2", longText), longText, false);
        assertNull(shared.find("t.p2", longText));
        assertEquals(0, shared.size());
    }

    @Test
    void theLeastRecentlyUsedUnit_isForgottenFirst() {
        ParsedUnits shared = new ParsedUnits(2, 1_000);
        for (String text : List.of("a := 1", "b := 2")) {
            shared.keep(Parser.parse("t.p2", text), text, false);
        }
        assertNotNull(shared.find("t.p2", "a := 1"));   // used: b is now the eldest
        shared.keep(Parser.parse("t.p2", "c := 3"), "c := 3", false);
        assertEquals(2, shared.size());
        assertNull(shared.find("t.p2", "b := 2"));
        assertNotNull(shared.find("t.p2", "a := 1"));
    }

    @Test
    void enginesSharingTheParse_eachRunEveryStatement() {
        ParsedUnits shared = new ParsedUnits(8, 1_000);
        List<String> first = new ArrayList<>();
        List<String> second = new ArrayList<>();
        PolicyEngine one = PolicyEngine.builder().output(first::add).parsedUnits(shared).build();
        PolicyEngine two = PolicyEngine.builder().output(second::add).parsedUnits(shared).build();
        assertEquals(RunResult.Status.OK, one.run("t.p2", TEXT).status());
        assertEquals(1, shared.size());
        assertEquals(RunResult.Status.OK, two.run("t.p2", TEXT).status());
        assertEquals(RunResult.Status.OK, two.run("t.p2", TEXT).status());
        assertEquals(List.of("7", "done"), first);
        assertEquals(List.of("7", "done", "7", "done"), second);
    }

    @Test
    void aUnitWithAnInclude_isParsedAgainWithTheFileAsItIsNow(@TempDir Path dir) throws Exception {
        ParsedUnits shared = new ParsedUnits(8, 1_000);
        Path main = dir.resolve("main.p2");
        Files.writeString(main, "include \"lib.p2\".\nroot print: \"main\"");
        Files.writeString(dir.resolve("lib.p2"), "root print: \"lib 1\"");
        List<String> lines = new ArrayList<>();
        assertEquals(RunResult.Status.OK, PolicyEngine.builder().output(lines::add).parsedUnits(shared).build()
                .runFile(main).status());
        Files.writeString(dir.resolve("lib.p2"), "root print: \"lib 2\"");
        assertEquals(RunResult.Status.OK, PolicyEngine.builder().output(lines::add).parsedUnits(shared).build()
                .runFile(main).status());
        assertEquals(List.of("lib 1", "main", "lib 2", "main"), lines);
        assertNull(shared.find(main.toString(), Files.readString(main)));
    }

    @Test
    void aSyntaxErrorIsReportedToEveryEngine() {
        ParsedUnits shared = new ParsedUnits(8, 1_000);
        for (int i = 0; i < 2; i++) {
            RunResult result = PolicyEngine.builder().parsedUnits(shared).build().run("t.p2", "a := (");
            assertEquals(RunResult.Status.SYNTAX_ERROR, result.status());
            assertEquals(1, result.diagnostics().size(), result.diagnostics().toString());
        }
        assertEquals(0, shared.size());
    }

    @Test
    void badBounds_areRefusedWithTheRule() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new ParsedUnits(0, 10));
        assertEquals("parsed units: at most 0 units of 10 characters; both must be 1 or more", e.getMessage());
    }
}
