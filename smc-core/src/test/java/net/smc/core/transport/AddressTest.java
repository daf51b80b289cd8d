package net.smc.core.transport;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetSocketAddress;
import java.util.List;
import java.util.TreeSet;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class AddressTest {

    @Test
    void toString_andParse_roundTrip() {
        Address a = Address.of("10.0.0.7", 4001);
        assertEquals("10.0.0.7:4001", a.toString());
        assertEquals(a, Address.parse("10.0.0.7:4001"));
    }

    @Test
    void loopback_isOnLocalhost() {
        assertEquals(new Address("127.0.0.1", 9), Address.loopback(9));
    }

    @ParameterizedTest
    @ValueSource(strings = {"0.0.0.0", "127.0.0.1", "255.255.255.255", "10.0.0.7", "192.168.100.1"})
    void isIpv4Literal_acceptsDottedQuads(String host) {
        assertTrue(Address.isIpv4Literal(host));
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "localhost", "1.2.3", "1.2.3.4.5", "256.0.0.1", "127.0.0.01", "1..2.3", "1.2.3.",
            ".1.2.3", "1.2.3.4 ", "-1.2.3.4", "1.2.3.1000", "::1"})
    void isIpv4Literal_refusesAnythingElse(String host) {
        assertFalse(Address.isIpv4Literal(host));
    }

    @Test
    void host_mustBeAnIpv4Literal() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Address.of("localhost", 80));
        assertEquals("host 'localhost' is not an IPv4 address literal; it must be four numbers 0-255 without leading zeros,"
                + " e.g. 127.0.0.1", e.getMessage());
    }

    @Test
    void port_mustBeInRange() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Address.of("127.0.0.1", 0));
        assertEquals("port 0 of host 127.0.0.1 is out of range; it must be 1 to 65535", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Address.of("127.0.0.1", 65_536));
    }

    @Test
    void parse_withoutPort_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Address.parse("127.0.0.1"));
        assertEquals("address '127.0.0.1' has no port; it must be host:port, e.g. 127.0.0.1:4000", e.getMessage());
    }

    @Test
    void parse_ofNonNumericPort_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Address.parse("127.0.0.1:http"));
        assertEquals("address '127.0.0.1:http' has port 'http'; it must be a number 1 to 65535", e.getMessage());
    }

    @Test
    void order_isNumericByHost_thenByPort() {
        TreeSet<Address> sorted = new TreeSet<>(List.of(Address.of("10.0.0.10", 1), Address.of("10.0.0.9", 2),
                Address.of("10.0.0.9", 1), Address.of("200.0.0.1", 1), Address.of("9.255.255.255", 5)));
        assertEquals("[9.255.255.255:5, 10.0.0.9:1, 10.0.0.9:2, 10.0.0.10:1, 200.0.0.1:1]", sorted.toString());
    }

    @Test
    void socketAddress_roundTrips() {
        Address a = Address.of("192.168.1.200", 4446);
        InetSocketAddress s = a.toInetSocketAddress();
        assertEquals("192.168.1.200", s.getAddress().getHostAddress());
        assertEquals(4446, s.getPort());
        assertEquals(a, Address.of(s));
    }

    @Test
    void unresolvedSocketAddress_isRefused() {
        InetSocketAddress unresolved = InetSocketAddress.createUnresolved("example.org", 80);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Address.of(unresolved));
        assertTrue(e.getMessage().endsWith("is not a resolved IPv4 address"), e.getMessage());
    }
}
