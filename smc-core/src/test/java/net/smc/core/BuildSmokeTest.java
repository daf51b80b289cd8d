package net.smc.core;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.netty.channel.epoll.Epoll;

import org.junit.jupiter.api.Test;

/** Checks that smc-core's tests see its package and the libraries the build gives it. */
class BuildSmokeTest {

    @Test
    void testClasses_liveInTheCorePackage() {
        assertEquals("net.smc.core", BuildSmokeTest.class.getPackageName());
    }

    @Test
    void jacksonXmlAndSlf4j_areOnTheTestClasspath() {
        assertDoesNotThrow(() -> Class.forName("com.fasterxml.jackson.dataformat.xml.XmlMapper"));
        assertDoesNotThrow(() -> Class.forName("org.slf4j.LoggerFactory"));
    }

    @Test
    void nettyEpollNativeLibrary_loads() {
        assertTrue(Epoll.isAvailable(), () -> "epoll unavailable: " + Epoll.unavailabilityCause());
    }
}
