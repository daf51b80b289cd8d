package net.smc.demo;

import java.io.IOException;
import java.time.Duration;
import java.util.concurrent.Callable;
import net.smc.core.transport.Address;
import net.smc.core.transport.udp.StatusClient;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

/**
 * {@code smc status --node ADDR:PORT}: asks a running node for its view ({@link StatusClient}, answered
 * by the node's {@code StatusResponder}) and prints the JSON it sends back, as received.
 */
@Command(name = "status", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = {
            "Asks a running node for its status and prints the JSON view it answers on standard output.",
            "The query is one UDP datagram to the node's unicast address, repeated up to 3 times within "
                    + "the timeout. It is read-only and unauthenticated: a node reveals only its view."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:the node answered; its JSON is printed",
            "1:no answer within the timeout (no node there, or the network lost every try)",
            "2:usage error: a bad --node or --timeout"})
final class StatusCommand implements Callable<Integer> {
    static final long DEFAULT_TIMEOUT_MILLIS = 2_000;
    private static final long MAX_TIMEOUT_MILLIS = 600_000;

    private final Io io;

    @Option(names = "--node", required = true, paramLabel = "ADDR:PORT", converter = AddressConverter.class,
            description = "The node's unicast address: an IPv4 address and a UDP port, e.g. 10.77.0.11:4000.")
    Address node;

    @Option(names = "--timeout", paramLabel = "MS", converter = TimeoutConverter.class,
            description = "How long to wait for the answer, in milliseconds, 1 to " + MAX_TIMEOUT_MILLIS
                    + " (default: " + DEFAULT_TIMEOUT_MILLIS + ").")
    long timeoutMillis = DEFAULT_TIMEOUT_MILLIS;

    StatusCommand(Io io) {
        this.io = io;
    }

    @Override
    public Integer call() {
        String json;
        try {
            json = StatusClient.query(node.toInetSocketAddress(), Duration.ofMillis(timeoutMillis));
        } catch (IOException e) {
            io.stderr().println("smc status: " + e.getMessage());
            io.stderr().flush();
            return 1;
        }
        io.stdout().println(json);
        io.stdout().flush();
        return 0;
    }

    /** A whole number of milliseconds, 1 to {@value #MAX_TIMEOUT_MILLIS}. */
    static final class TimeoutConverter implements ITypeConverter<Long> {
        @Override
        public Long convert(String value) {
            long millis;
            try {
                millis = Long.parseLong(value);
            } catch (NumberFormatException e) {
                millis = -1;
            }
            if (millis < 1 || millis > MAX_TIMEOUT_MILLIS) {
                throw new TypeConversionException("'" + value + "' is not a timeout; expected milliseconds, 1 to "
                        + MAX_TIMEOUT_MILLIS + ", e.g. 500");
            }
            return millis;
        }
    }
}
