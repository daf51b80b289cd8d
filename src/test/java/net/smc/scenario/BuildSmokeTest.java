package net.smc.scenario;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** Checks that scenario tests run against every module, with the project's folders passed in. */
class BuildSmokeTest {

    @Test
    void testClasses_liveInTheScenarioPackage() {
        assertEquals("net.smc.scenario", BuildSmokeTest.class.getPackageName());
    }

    @Test
    void projectDir_isTheRepositoryRoot() {
        String project = System.getProperty("smc.project.dir");
        assertNotNull(project, "system property smc.project.dir");
        assertTrue(Files.isRegularFile(Path.of(project, "settings.gradle")), "settings.gradle in " + project);
        assertEquals(Path.of(project, "policies").toString(), System.getProperty("smc.repo.dir"));
    }

    @Test
    void librariesOfEveryModule_areOnTheClasspath() {
        assertDoesNotThrow(() -> Class.forName("io.netty.channel.epoll.Epoll"));    // smc-core
        assertDoesNotThrow(() -> Class.forName("org.dyn4j.world.World"));           // smc-sim
        assertDoesNotThrow(() -> Class.forName("picocli.CommandLine"));             // smc-demo
    }
}
