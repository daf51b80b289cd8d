package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The costs measured on this machine (a few seconds: each operation is warmed up and timed in batches). */
class CalibrationTest {
    @TempDir
    Path dir;

    @Test
    void measuresEveryCost_andVerifiesSignaturesForReal() throws Exception {
        Path boot = Project.bootEvents();
        CpuCosts c = Calibration.measure(boot, MissionGenerator.write(TreeShape.of(20, 4), dir, boot));
        // An Ed25519 verification is tens of microseconds or more on any machine; a signature found
        // in the security layer's memo of valid ones takes a fraction of one.
        assertTrue(c.verifyNanos() > 10_000, c.toString());
        assertTrue(c.signNanos() > 10_000 && c.agreeNanos() > 10_000, c.toString());
        assertTrue(c.loadNanosPerByte() > 0 && c.codecNanosPerByte() > 0, c.toString());
        // Deflating costs more per byte than inflating, and both far less than loading the text.
        assertTrue(c.deflateNanosPerByte() > 0 && c.deflateNanosPerByte() < c.loadNanosPerByte(), c.toString());
        assertTrue(c.inflateNanosPerByte() < c.loadNanosPerByte(), c.toString());
    }
}
