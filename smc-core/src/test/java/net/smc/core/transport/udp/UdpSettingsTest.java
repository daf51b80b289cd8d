package net.smc.core.transport.udp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class UdpSettingsTest {
    private final UdpSettings defaults = UdpSettings.defaults();

    @Test
    void defaults_areForOneMachine() {
        assertEquals(new UdpSettings("127.0.0.1", 0, null, "127.255.255.255", 47_474, 1 << 20), defaults);
        assertEquals("127.0.0.1", defaults.reachableHost());
    }

    @Test
    void withers_changeOneThingEach() {
        UdpSettings s = defaults.withBindHost("0.0.0.0", "10.0.0.7").withPort(4001)
                .withBroadcast("10.0.0.255", 5000).withReceiveBufferBytes(65_536);
        assertEquals(new UdpSettings("0.0.0.0", 4001, "10.0.0.7", "10.0.0.255", 5000, 65_536), s);
        assertEquals("10.0.0.7", s.reachableHost());
    }

    @Test
    void hosts_mustBeIpv4Literals() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> defaults.withBindHost("localhost"));
        assertEquals("bindHost 'localhost' is not an IPv4 address literal, e.g. 127.0.0.1", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> defaults.withBroadcast("broadcast", 5000));
        assertThrows(IllegalArgumentException.class, () -> defaults.withAdvertisedHost("me"));
    }

    @Test
    void wildcardBind_needsAnAdvertisedHost() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> defaults.withBindHost("0.0.0.0"));
        assertEquals("bindHost 0.0.0.0 needs an advertisedHost: other cells must know where to reply", e.getMessage());
    }

    @Test
    void wildcard_cannotBeAdvertised() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> defaults.withAdvertisedHost("0.0.0.0"));
        assertEquals("advertisedHost 0.0.0.0 cannot be reached; it must be an address of this host", e.getMessage());
    }

    @Test
    void ports_mustBeInRange() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> defaults.withPort(70_000));
        assertEquals("port 70000 is out of range; it must be 0 (any free port) to 65535", e.getMessage());
        IllegalArgumentException b = assertThrows(IllegalArgumentException.class, () -> defaults.withBroadcast("127.255.255.255", 0));
        assertEquals("broadcastPort 0 is out of range; it must be 1 to 65535", b.getMessage());
    }

    @Test
    void unicastPort_mustDifferFromTheBroadcastPort() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> defaults.withPort(47_474));
        assertEquals("port 47474 equals broadcastPort; each cell needs a unicast port of its own, apart from the shared "
                + "broadcast port", e.getMessage());
    }

    @Test
    void receiveBuffer_hasAFloor() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> defaults.withReceiveBufferBytes(1_000));
        assertEquals("receiveBufferBytes 1000 is too small; it must be at least 16384", e.getMessage());
    }
}
