package net.smc.policy.lang;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SourceFilesTest {
    @TempDir
    Path dir;

    private final List<Diagnostic> errors = new ArrayList<>();
    private final List<String> output = new ArrayList<>();
    private final PolicyEngine cell = PolicyEngine.builder().errors(errors::add).output(output::add).build();

    @Test
    void latin1Bytes_areRefusedWithTheirByteOffsetAndLine() throws IOException {
        Path file = dir.resolve("latin1.p2");
        Files.write(file, "root print: 1.\nroot print: \"caf\u00e9\".\n".getBytes(StandardCharsets.ISO_8859_1));

        RunResult result = cell.runFile(file);

        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status());
        assertEquals(1, errors.size());
        assertEquals(file + ": cannot read: not valid UTF-8: byte 0xE9 at byte offset 31 (line 2) is not part of a "
                + "well-formed character; save the file as UTF-8 (or as UTF-16 with a byte-order mark)",
                errors.get(0).message());
        assertTrue(output.isEmpty(), "nothing of a refused file runs");
    }

    @Test
    void aReplacementCharacterWrittenInTheFile_isText_notAnError() throws IOException {
        Path file = dir.resolve("fffd.p2");
        Files.writeString(file, "root print: \"a\uFFFDb\".\n");

        cell.runFile(file);

        assertEquals(List.of(), errors);
        assertEquals(List.of("a\uFFFDb"), output);
    }

    @Test
    void utf16WithAByteOrderMark_andUtf8WithOne_areRead() throws IOException {
        Path le = dir.resolve("le.p2");
        Files.write(le, concat(new byte[] {(byte) 0xFF, (byte) 0xFE}, "root print: \"\u00e9t\u00e9\".".getBytes(StandardCharsets.UTF_16LE)));
        Path be = dir.resolve("be.p2");
        Files.write(be, concat(new byte[] {(byte) 0xFE, (byte) 0xFF}, "root print: 2.".getBytes(StandardCharsets.UTF_16BE)));
        Path bom8 = dir.resolve("bom8.p2");
        Files.write(bom8, concat(new byte[] {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF}, "root print: 3.".getBytes(StandardCharsets.UTF_8)));

        cell.runFile(le);
        cell.runFile(be);
        cell.runFile(bom8);

        assertEquals(List.of(), errors);
        assertEquals(List.of("\u00e9t\u00e9", "2", "3"), output);
    }

    @Test
    void aFileLargerThanAnyUnit_isRefusedUnread() throws IOException {
        Path file = dir.resolve("big.p2");
        Files.write(file, new byte[50]);

        IOException e = assertThrows(IOException.class, () -> SourceFiles.read(file, 10));

        assertEquals("file of 50 bytes is larger than a unit may be (at most 10 characters)", e.getMessage());
    }

    private static byte[] concat(byte[] a, byte[] b) {
        byte[] out = new byte[a.length + b.length];
        System.arraycopy(a, 0, out, 0, a.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }
}
