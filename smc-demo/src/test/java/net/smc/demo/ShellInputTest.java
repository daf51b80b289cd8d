package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.ByteArrayInputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

class ShellInputTest {

    private static ShellInput reading(String stdin) {
        return new ShellInput(new Io(new ByteArrayInputStream(stdin.getBytes(StandardCharsets.UTF_8)),
                new PrintWriter(new StringWriter()), new PrintWriter(new StringWriter()), false, Path.of("")));
    }

    @Test
    void inputEnds_atALineEndingInADot_afterTrailingWhitespace() throws Exception {
        ShellInput input = reading("a := 1\n b.  \t\nc.\n");

        assertEquals("a := 1\n b.  \t\n", input.next(org.junit.jupiter.api.Assertions::fail));
        assertEquals("c.\n", input.next(org.junit.jupiter.api.Assertions::fail));
        assertNull(input.next(org.junit.jupiter.api.Assertions::fail));
    }

    @Test
    void blankLinesBeforeAnInput_areSkipped_butKeptInsideOne() throws Exception {
        ShellInput input = reading("\n  \nx\n\ny.\n\n");

        assertEquals("x\n\ny.\n", input.next(org.junit.jupiter.api.Assertions::fail));
        assertNull(input.next(org.junit.jupiter.api.Assertions::fail));
    }

    @Test
    void aDotInsideTheLine_doesNotEndTheInput() throws Exception {
        ShellInput input = reading("x := 1. y := 2\n.\n");

        assertEquals("x := 1. y := 2\n.\n", input.next(org.junit.jupiter.api.Assertions::fail));
    }

    @Test
    void textWithoutAFinalDot_isTheLastInput() throws Exception {
        ShellInput input = reading("x.\ny");

        assertEquals("x.\n", input.next(org.junit.jupiter.api.Assertions::fail));
        assertEquals("y\n", input.next(org.junit.jupiter.api.Assertions::fail));
        assertNull(input.next(org.junit.jupiter.api.Assertions::fail));
    }

    /** Lines as a terminal's line editor gives them, recording the prompt shown before each. */
    private static final class Scripted implements ShellInput.LineSource {
        final java.util.Iterator<String> lines;
        final java.util.List<String> prompts = new java.util.ArrayList<>();
        int ended;

        Scripted(String... lines) {
            this.lines = java.util.List.of(lines).iterator();
        }

        @Override
        public String readLine(String prompt) {
            prompts.add(prompt);
            return lines.hasNext() ? lines.next() : null;
        }

        @Override
        public void ended() {
            ended++;
        }
    }

    @Test
    void aLineEditor_isPromptedForEachLine_withTheContinuationPromptInsideAnUnfinishedInput() throws Exception {
        Scripted terminal = new Scripted("x := 1", "  + 2.", "", "y.");
        ShellInput input = new ShellInput(terminal);

        assertEquals("x := 1\n  + 2.\n", input.next(org.junit.jupiter.api.Assertions::fail));
        assertEquals("y.\n", input.next(org.junit.jupiter.api.Assertions::fail));
        assertNull(input.next(org.junit.jupiter.api.Assertions::fail));
        assertEquals(java.util.List.of("smc> ", "...> ", "smc> ", "smc> ", "smc> "), terminal.prompts);
        assertEquals(1, terminal.ended);
    }

    @Test
    void aLineEditorEndingInsideAnInput_runsWhatItHas() throws Exception {
        Scripted terminal = new Scripted("a := 1", "b := a + 1");
        ShellInput input = new ShellInput(terminal);

        assertEquals("a := 1\nb := a + 1\n", input.next(org.junit.jupiter.api.Assertions::fail));
        assertEquals(java.util.List.of("smc> ", "...> ", "...> "), terminal.prompts);
        assertNull(input.next(org.junit.jupiter.api.Assertions::fail));
    }
}
