package net.smc.core.transport;

import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.util.Objects;

/**
 * Where a cell can be reached: an IPv4 address literal and a UDP port, the same form in simulation
 * and in deployment, so protocol code, traces and messages never care which network carries them.
 *
 * <p>Only IPv4 literals are accepted ({@code 127.0.0.1}, {@code 10.0.0.7}): cells find each other by
 * broadcast, which IPv6 does not have, and a literal never needs a name lookup (which would be I/O
 * inside a value type). The in-memory network uses the same form, usually {@code 127.0.0.1} with
 * one port per node ({@link #loopback(int)}), so a simulated trace reads like a real one.
 *
 * <p>Addresses are ordered by the numeric value of the host, then by port; the in-memory network
 * relies on this order to fan out broadcasts deterministically.
 *
 * @param host an IPv4 address in dotted-quad form without leading zeros, e.g. {@code 127.0.0.1}
 * @param port a UDP port, 1 to 65535
 */
public record Address(String host, int port) implements Comparable<Address> {

    public Address {
        Objects.requireNonNull(host, "host");
        if (parseIpv4(host) < 0) {
            throw new IllegalArgumentException("host '" + host
                    + "' is not an IPv4 address literal; it must be four numbers 0-255 without leading zeros, e.g. 127.0.0.1");
        }
        if (port < 1 || port > 65_535) {
            throw new IllegalArgumentException("port " + port + " of host " + host + " is out of range; it must be 1 to 65535");
        }
    }

    /** The address {@code host:port}. */
    public static Address of(String host, int port) {
        return new Address(host, port);
    }

    /** {@code 127.0.0.1:port}: the usual form of a simulated node, and of a cell on one machine. */
    public static Address loopback(int port) {
        return new Address("127.0.0.1", port);
    }

    /** Parses {@code host:port}, e.g. {@code 127.0.0.1:4000}, as written by {@link #toString()}. */
    public static Address parse(String text) {
        Objects.requireNonNull(text, "text");
        int colon = text.lastIndexOf(':');
        if (colon < 0) {
            throw new IllegalArgumentException("address '" + text + "' has no port; it must be host:port, e.g. 127.0.0.1:4000");
        }
        int port;
        try {
            port = Integer.parseInt(text.substring(colon + 1));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("address '" + text + "' has port '" + text.substring(colon + 1)
                    + "'; it must be a number 1 to 65535", e);
        }
        return new Address(text.substring(0, colon), port);
    }

    /** The address of a socket; it must be a resolved IPv4 address. */
    public static Address of(InetSocketAddress socketAddress) {
        InetAddress ip = socketAddress.getAddress();
        if (!(ip instanceof Inet4Address)) {
            throw new IllegalArgumentException("socket address " + socketAddress + " is not a resolved IPv4 address");
        }
        return new Address(ip.getHostAddress(), socketAddress.getPort());
    }

    /** The socket address of this address; no name lookup happens. */
    public InetSocketAddress toInetSocketAddress() {
        long ip = parseIpv4(host);
        byte[] bytes = {(byte) (ip >>> 24), (byte) (ip >>> 16), (byte) (ip >>> 8), (byte) ip};
        try {
            return new InetSocketAddress(InetAddress.getByAddress(bytes), port);
        } catch (UnknownHostException e) {
            throw new AssertionError("four bytes are always a valid IPv4 address", e);
        }
    }

    /** Whether {@code text} is an IPv4 address in the form this type accepts, e.g. {@code 10.0.0.7}. */
    public static boolean isIpv4Literal(String text) {
        return text != null && parseIpv4(text) >= 0;
    }

    @Override
    public int compareTo(Address other) {
        if (host.equals(other.host)) {   // the usual case in simulation (one host, a port per node): no parsing
            return Integer.compare(port, other.port);
        }
        int byHost = Long.compare(parseIpv4(host), parseIpv4(other.host));
        return byHost != 0 ? byHost : Integer.compare(port, other.port);
    }

    @Override
    public String toString() {
        return host + ":" + port;
    }

    /** The 32-bit value of a canonical dotted quad, or -1 (as a long) when the text is not one. */
    private static long parseIpv4(String text) {
        long value = 0;
        int octets = 0;
        int i = 0;
        int n = text.length();
        while (i <= n) {
            int start = i;
            int octet = 0;
            while (i < n && text.charAt(i) >= '0' && text.charAt(i) <= '9') {
                octet = octet * 10 + (text.charAt(i) - '0');
                i++;
                if (i - start > 3) {
                    return -1;
                }
            }
            int digits = i - start;
            if (digits == 0 || octet > 255 || (digits > 1 && text.charAt(start) == '0')) {
                return -1;
            }
            value = (value << 8) | octet;
            octets++;
            if (i == n) {
                break;
            }
            if (text.charAt(i) != '.' || octets == 4) {
                return -1;
            }
            i++;
        }
        return octets == 4 ? value : -1;
    }
}
