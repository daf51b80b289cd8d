package net.smc.core.transport.udp;

import java.util.Objects;

import net.smc.core.transport.Address;

/**
 * Where a {@link UdpTransport} binds and broadcasts. Hosts are IPv4 literals; ports are UDP ports;
 * sizes are bytes. Start from {@link #defaults()} (one machine, loopback) and change what differs:
 * <pre>{@code
 * UdpSettings.defaults().withPort(4001)                                     // one machine
 * UdpSettings.defaults().withBindHost("0.0.0.0", "10.0.0.7")
 *         .withBroadcast("10.0.0.255", 47474)                               // a subnet
 * }</pre>
 *
 * @param bindHost           the host the cell's unicast channel binds: {@code 127.0.0.1} on one machine,
 *                           the host's address, or {@code 0.0.0.0} for every interface (default {@code 127.0.0.1})
 * @param port               the unicast port, 0 for any free one (default 0); each cell needs its own
 * @param advertisedHost     the host other cells reach this one at; null means {@code bindHost}, and is
 *                           not allowed when {@code bindHost} is {@code 0.0.0.0} (default null)
 * @param broadcastHost      the broadcast address: {@code 127.255.255.255} on one machine, the subnet's
 *                           broadcast address elsewhere (default {@code 127.255.255.255})
 * @param broadcastPort      the port every cell of a team shares for broadcasts, bound on {@code 0.0.0.0}
 *                           with SO_REUSEADDR (default {@value #DEFAULT_BROADCAST_PORT})
 * @param receiveBufferBytes the kernel's receive buffer of each channel (SO_RCVBUF), at least
 *                           {@value #MIN_RECEIVE_BUFFER_BYTES}; the kernel caps it at
 *                           {@code net.core.rmem_max} (default 1 MiB: a burst of a thousand small
 *                           datagrams fits)
 */
public record UdpSettings(String bindHost, int port, String advertisedHost, String broadcastHost,
                          int broadcastPort, int receiveBufferBytes) {

    public static final int DEFAULT_BROADCAST_PORT = 47_474;
    public static final int MIN_RECEIVE_BUFFER_BYTES = 16 * 1024;
    static final String WILDCARD = "0.0.0.0";

    public UdpSettings {
        checkHost("bindHost", bindHost);
        if (port < 0 || port > 65_535) {
            throw new IllegalArgumentException("port " + port + " is out of range; it must be 0 (any free port) to 65535");
        }
        if (advertisedHost != null) {
            checkHost("advertisedHost", advertisedHost);
            if (advertisedHost.equals(WILDCARD)) {
                throw new IllegalArgumentException("advertisedHost 0.0.0.0 cannot be reached; it must be an address of this host");
            }
        } else if (bindHost.equals(WILDCARD)) {
            throw new IllegalArgumentException("bindHost 0.0.0.0 needs an advertisedHost: other cells must know where to reply");
        }
        checkHost("broadcastHost", broadcastHost);
        if (broadcastPort < 1 || broadcastPort > 65_535) {
            throw new IllegalArgumentException("broadcastPort " + broadcastPort + " is out of range; it must be 1 to 65535");
        }
        if (port == broadcastPort) {
            throw new IllegalArgumentException("port " + port + " equals broadcastPort; each cell needs a unicast port "
                    + "of its own, apart from the shared broadcast port");
        }
        if (receiveBufferBytes < MIN_RECEIVE_BUFFER_BYTES) {
            throw new IllegalArgumentException("receiveBufferBytes " + receiveBufferBytes + " is too small; it must be at least "
                    + MIN_RECEIVE_BUFFER_BYTES);
        }
    }

    /** One machine: bind 127.0.0.1 on any free port, broadcast to 127.255.255.255:{@value #DEFAULT_BROADCAST_PORT}. */
    public static UdpSettings defaults() {
        return new UdpSettings("127.0.0.1", 0, null, "127.255.255.255", DEFAULT_BROADCAST_PORT, 1 << 20);
    }

    public UdpSettings withBindHost(String bindHost) {
        return new UdpSettings(bindHost, port, advertisedHost, broadcastHost, broadcastPort, receiveBufferBytes);
    }

    /** Binds {@code bindHost} and tells other cells to reply to {@code advertisedHost} (null: to {@code bindHost}). */
    public UdpSettings withBindHost(String bindHost, String advertisedHost) {
        return new UdpSettings(bindHost, port, advertisedHost, broadcastHost, broadcastPort, receiveBufferBytes);
    }

    public UdpSettings withPort(int port) {
        return new UdpSettings(bindHost, port, advertisedHost, broadcastHost, broadcastPort, receiveBufferBytes);
    }

    public UdpSettings withAdvertisedHost(String advertisedHost) {
        return new UdpSettings(bindHost, port, advertisedHost, broadcastHost, broadcastPort, receiveBufferBytes);
    }

    public UdpSettings withBroadcast(String broadcastHost, int broadcastPort) {
        return new UdpSettings(bindHost, port, advertisedHost, broadcastHost, broadcastPort, receiveBufferBytes);
    }

    public UdpSettings withReceiveBufferBytes(int receiveBufferBytes) {
        return new UdpSettings(bindHost, port, advertisedHost, broadcastHost, broadcastPort, receiveBufferBytes);
    }

    /** The host other cells reach this one at. */
    public String reachableHost() {
        return advertisedHost != null ? advertisedHost : bindHost;
    }

    private static void checkHost(String name, String host) {
        Objects.requireNonNull(host, name);
        if (!Address.isIpv4Literal(host)) {
            throw new IllegalArgumentException(name + " '" + host + "' is not an IPv4 address literal, e.g. 127.0.0.1");
        }
    }
}
