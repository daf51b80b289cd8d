package net.smc.core.transport;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/** Netty is used only inside the UDP transport package, so the rest of the project never depends on it. */
class NettyConfinementTest {

    @Test
    void onlyTheUdpPackage_importsNetty() throws IOException {
        Path sources = Path.of(System.getProperty("smc.project.dir"), "smc-core", "src", "main", "java");
        Path udp = sources.resolve(Path.of("net", "smc", "core", "transport", "udp"));
        assertTrue(Files.isDirectory(udp), udp + " exists");
        try (Stream<Path> files = Files.walk(sources)) {
            List<String> offenders = files
                    .filter(f -> f.toString().endsWith(".java") && !f.startsWith(udp))
                    .filter(NettyConfinementTest::mentionsNetty)
                    .map(f -> sources.relativize(f).toString())
                    .sorted()
                    .toList();
            assertEquals(List.of(), offenders, "files outside net.smc.core.transport.udp that use io.netty");
        }
    }

    private static boolean mentionsNetty(Path file) {
        try {
            return Files.readString(file).contains("io.netty.");
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
