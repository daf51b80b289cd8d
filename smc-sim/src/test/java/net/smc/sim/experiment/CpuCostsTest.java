package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CpuCostsTest {
    private static final CpuCosts COSTS = new CpuCosts(60_000, 120_000, 90_000, 800, 4, 600, 3, 3_000, 500, 20, 5);

    @TempDir
    Path dir;

    @Test
    void savedCosts_loadBackTheSame_withNothingDefaulted() throws IOException {
        Path file = dir.resolve("costs.properties");
        COSTS.save(file);
        List<String> notes = new ArrayList<>();
        assertEquals(COSTS, CpuCosts.load(file, notes::add));
        assertEquals(List.of(), notes);
    }

    /** The costs file of the README's Fig. 8 was written before compression: it still replays. */
    @Test
    void aFileWithoutTheCompressionCosts_getsTheirDefaults_andSaysSo() throws IOException {
        Path file = dir.resolve("old.properties");
        Files.writeString(file, """
                verifyNanos=350298.8
                codecNanosPerByte=8.6
                macNanos=11749.5
                macNanosPerByte=0.0
                agreeNanos=676307.1
                conditionNanos=2445.5
                signNanos=241635.8
                loadNanosPerByte=4617.4
                codecNanos=858.4
                """);
        List<String> notes = new ArrayList<>();
        CpuCosts costs = CpuCosts.load(file, notes::add);
        assertEquals(new CpuCosts(241_635.8, 350_298.8, 676_307.1, 11_749.5, 0, 858.4, 8.6, 4_617.4, 2_445.5,
                CpuCosts.DEFAULT_DEFLATE_NANOS_PER_BYTE, CpuCosts.DEFAULT_INFLATE_NANOS_PER_BYTE), costs);
        assertEquals(List.of(
                file + " has no 'deflateNanosPerByte' (written before policy texts were compressed): "
                        + String.format(java.util.Locale.ROOT, "%.1f", CpuCosts.DEFAULT_DEFLATE_NANOS_PER_BYTE)
                        + " ns, the default",
                file + " has no 'inflateNanosPerByte' (written before policy texts were compressed): "
                        + String.format(java.util.Locale.ROOT, "%.1f", CpuCosts.DEFAULT_INFLATE_NANOS_PER_BYTE)
                        + " ns, the default"), notes);
    }

    @Test
    void anyOtherMissingCost_isStillAnError() throws IOException {
        Path file = dir.resolve("partial.properties");
        Files.writeString(file, "signNanos=1\n");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CpuCosts.load(file));
        assertEquals(file + ": no 'verifyNanos'; a costs file lists every cost of CpuCosts", e.getMessage());
    }

    @Test
    void aMalformedCompressionCost_isAnError() throws IOException {
        Path file = dir.resolve("bad.properties");
        COSTS.save(file);
        Files.writeString(file, Files.readString(file).replace("inflateNanosPerByte=5.0", "inflateNanosPerByte=fast"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CpuCosts.load(file));
        assertEquals(file + ": 'inflateNanosPerByte' is 'fast', not a number of nanoseconds", e.getMessage());
    }
}
