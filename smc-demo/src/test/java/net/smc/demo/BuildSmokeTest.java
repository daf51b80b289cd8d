package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Checks that smc-demo's tests see its package and the libraries the build gives it. */
class BuildSmokeTest {

    @Test
    void testClasses_liveInTheDemoPackage() {
        assertEquals("net.smc.demo", BuildSmokeTest.class.getPackageName());
    }

    @Test
    void picocliAndXChart_areOnTheTestClasspath() {
        assertDoesNotThrow(() -> Class.forName("picocli.CommandLine"));
        assertDoesNotThrow(() -> Class.forName("org.knowm.xchart.XYChart"));
    }
}
