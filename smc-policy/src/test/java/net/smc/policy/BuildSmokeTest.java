package net.smc.policy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** Checks the build's promises to smc-policy's tests: package, golden folder, resources. */
class BuildSmokeTest {

    @Test
    void testClasses_liveInThePolicyPackage() {
        assertEquals("net.smc.policy", BuildSmokeTest.class.getPackageName());
    }

    @Test
    void goldenDir_isPassedToTheTestJvmAndExists() {
        String golden = System.getProperty("smc.golden.dir");
        assertNotNull(golden, "system property smc.golden.dir");
        Path dir = Path.of(golden);
        assertTrue(dir.isAbsolute(), "smc.golden.dir is absolute: " + dir);
        assertTrue(dir.endsWith(Path.of("smc-policy", "src", "test", "resources", "golden")), dir.toString());
        assertTrue(Files.isDirectory(dir), "smc.golden.dir exists: " + dir);
    }

    @Test
    void testResources_areOnTheClasspath() {
        assertNotNull(BuildSmokeTest.class.getResource("/golden"), "resource folder /golden");
    }
}
