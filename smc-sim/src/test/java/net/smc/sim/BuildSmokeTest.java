package net.smc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.dyn4j.geometry.Vector2;
import org.junit.jupiter.api.Test;

/** Checks that smc-sim's tests see its package and compile against dyn4j. */
class BuildSmokeTest {

    @Test
    void testClasses_liveInTheSimPackage() {
        assertEquals("net.smc.sim", BuildSmokeTest.class.getPackageName());
    }

    @Test
    void dyn4j_isOnTheTestClasspath() {
        assertEquals(5.0, new Vector2(3.0, 4.0).getMagnitude(), 1e-12);
    }
}
