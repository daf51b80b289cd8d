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

        assertEquals("a := 1\n b.  \t\n", input.next());
        assertEquals("c.\n", input.next());
        assertNull(input.next());
    }

    @Test
    void blankLinesBeforeAnInput_areSkipped_butKeptInsideOne() throws Exception {
        ShellInput input = reading("\n  \nx\n\ny.\n\n");

        assertEquals("x\n\ny.\n", input.next());
        assertNull(input.next());
    }

    @Test
    void aDotInsideTheLine_doesNotEndTheInput() throws Exception {
        ShellInput input = reading("x := 1. y := 2\n.\n");

        assertEquals("x := 1. y := 2\n.\n", input.next());
    }

    @Test
    void textWithoutAFinalDot_isTheLastInput() throws Exception {
        ShellInput input = reading("x.\ny");

        assertEquals("x.\n", input.next());
        assertEquals("y\n", input.next());
        assertNull(input.next());
    }
}
