package net.smc.core.security;

import static net.smc.core.security.Team.HOUR;
import static net.smc.core.security.Team.MISSION;
import static net.smc.core.security.Team.T0;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import net.smc.core.security.Unwrapped.ControlEvent;
import org.junit.jupiter.api.Test;

/** Handshakes and the MAC'd traffic of a session: how sessions form, recover, and refuse what is not theirs. */
class SessionTest {
    private final Team team = new Team(4);
    private final SecureEndpoint a = team.endpoint("uav-a");
    private final SecureEndpoint b = team.endpoint("uav-b");
    private final byte[] heartbeat = "HB seq=17 pos=(12.5,-3.0) battery=81".getBytes(StandardCharsets.UTF_8);

    private static Unwrapped.Control control(Unwrapped u) {
        return assertInstanceOf(Unwrapped.Control.class, u, "expected a handshake step: " + u);
    }

    private Unwrapped.Rejected refusedBy(SecureEndpoint to, byte[] datagram, Rejection reason) {
        String before = Team.state(to);
        Unwrapped.Rejected r = assertInstanceOf(Unwrapped.Rejected.class, to.unwrap(datagram));
        assertEquals(reason, r.reason(), r.detail());
        assertEquals(before, Team.state(to), "a refused datagram changes nothing");
        return r;
    }

    @Test
    void handshake_bindsFreshValuesOfBothSides_andThenMacdTrafficFlowsBothWays() {
        byte[] hello = a.startHandshake("uav-b");
        Unwrapped.Control atB = control(b.unwrap(hello));
        assertEquals(ControlEvent.HANDSHAKE_OFFERED, atB.event(), "a's HELLO does not echo b's value: it may be a replay");
        assertFalse(b.hasSession("uav-a"));
        assertNotNull(atB.reply(), "b offers its value");

        Unwrapped.Control atA = control(a.unwrap(atB.reply()));
        assertEquals(ControlEvent.KEYS_AGREED, atA.event(), "b echoed a's value: fresh");
        assertNotNull(atA.reply(), "a echoes b's value so that b can agree");

        Unwrapped.Control atB2 = control(b.unwrap(atA.reply()));
        assertEquals(ControlEvent.KEYS_AGREED, atB2.event());
        Unwrapped.Control atA2 = control(a.unwrap(atB2.reply()));
        assertEquals(ControlEvent.HANDSHAKE_REPEATED, atA2.event());
        assertNull(atA2.reply(), "both agreed: nothing more to say");

        Unwrapped.Delivered d = assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(a.wrapFor("uav-b", heartbeat)));
        assertEquals("uav-a", d.sender());
        assertEquals(Protection.PAIR_MAC, d.protection());
        assertArrayEquals(heartbeat, d.payload());
        assertInstanceOf(Unwrapped.Delivered.class, a.unwrap(b.wrapFor("uav-a", heartbeat)));
    }

    @Test
    void crossingHandshakes_agreeOnOneSession() {
        byte[] fromA = a.startHandshake("uav-b");
        byte[] fromB = b.startHandshake("uav-a");

        byte[] replyFromB = control(b.unwrap(fromA)).reply();
        byte[] replyFromA = control(a.unwrap(fromB)).reply();
        byte[] lastFromA = control(a.unwrap(replyFromB)).reply();
        byte[] lastFromB = control(b.unwrap(replyFromA)).reply();
        assertNull(control(b.unwrap(lastFromA)).reply());
        assertNull(control(a.unwrap(lastFromB)).reply());

        assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(a.wrapFor("uav-b", heartbeat)));
        assertInstanceOf(Unwrapped.Delivered.class, a.unwrap(b.wrapFor("uav-a", heartbeat)));
    }

    @Test
    void lostReply_isRecoveredByARetry_withTheSameKeys() {
        byte[] offer = control(b.unwrap(a.startHandshake("uav-b"))).reply();
        control(a.unwrap(offer));   // a agrees; its answer is lost
        assertTrue(a.hasSession("uav-b"));
        assertFalse(b.hasSession("uav-a"));
        assertFalse(b.needsHandshake("uav-a"), "a retry waits for the retry interval");

        team.clock.advance(1_000);
        assertTrue(b.needsHandshake("uav-a"));
        Unwrapped.Control again = control(a.unwrap(b.startHandshake("uav-a")));
        assertEquals(ControlEvent.HANDSHAKE_REPEATED, again.event(), "a's session stands");
        Unwrapped.Control atB = control(b.unwrap(again.reply()));
        assertEquals(ControlEvent.KEYS_AGREED, atB.event(), "a's answer to b's retry echoes b's value");
        assertNull(control(a.unwrap(atB.reply())).reply(), "a answered within the retry interval: done");

        assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(a.wrapFor("uav-b", heartbeat)));
        assertInstanceOf(Unwrapped.Delivered.class, a.unwrap(b.wrapFor("uav-a", heartbeat)));
    }

    @Test
    void restartedPeer_setsUpANewSession_whichReplacesTheOld() {
        Team.shakeHands(a, b);
        team.clock.advance(5);
        SecureEndpoint bAgain = team.endpoint(b.identity);

        assertEquals(4, Team.shakeHands(bAgain, a));

        assertInstanceOf(Unwrapped.Delivered.class, bAgain.unwrap(a.wrapFor("uav-b", heartbeat)));
        assertInstanceOf(Unwrapped.Delivered.class, a.unwrap(bAgain.wrapFor("uav-a", heartbeat)));
    }

    @Test
    void aReplayedHandshake_neverAgreesKeys_withARestartedVehicle_whoStillJoins() {
        List<byte[]> fromA = new ArrayList<>();
        byte[] next = a.startHandshake("uav-b");
        SecureEndpoint to = b;
        while (next != null) {   // record a's side of a whole handshake
            if (to == b) {
                fromA.add(next);
            }
            next = ((Unwrapped.Control) to.unwrap(next)).reply();
            to = to == a ? b : a;
        }
        team.clock.advance(50);
        SecureEndpoint bAgain = team.endpoint(b.identity);   // b restarts: new values, no memory

        for (byte[] recorded : fromA) {
            Unwrapped u = bAgain.unwrap(recorded);
            if (u instanceof Unwrapped.Control c) {
                assertEquals(ControlEvent.HANDSHAKE_OFFERED, c.event(), "a replay agrees nothing");
            }
            assertFalse(bAgain.hasSession("uav-a"), "a replay sets up no session");
        }

        team.clock.advance(1_000);
        assertTrue(Team.shakeHands(bAgain, a) > 0);
        assertInstanceOf(Unwrapped.Delivered.class, bAgain.unwrap(a.wrapFor("uav-b", heartbeat)));
        assertInstanceOf(Unwrapped.Delivered.class, a.unwrap(bAgain.wrapFor("uav-a", heartbeat)));
    }

    @Test
    void aReplayedOrForgedOffer_leavesAnEstablishedSessionStanding() {
        Team.shakeHands(a, b);
        SecureEndpoint c = team.endpoint("uav-c");
        team.clock.advance(5);
        // a fresh HELLO from a third vehicle, and a's own HELLO re-sent: neither touches the a-b session
        control(b.unwrap(c.startHandshake("uav-b")));
        assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(a.wrapFor("uav-b", heartbeat)));
        assertInstanceOf(Unwrapped.Delivered.class, a.unwrap(b.wrapFor("uav-a", heartbeat)));
    }

    @Test
    void olderHandshake_arrivingLate_isRefusedAsReplay() {
        byte[] first = a.startHandshake("uav-b");
        team.clock.advance(1_000);
        byte[] second = a.startHandshake("uav-b");
        control(b.unwrap(second));

        Unwrapped.Rejected r = refusedBy(b, first, Rejection.REPLAY);

        assertTrue(r.detail().contains("is not after the newest handshake taken from it"), r.detail());
    }

    @Test
    void handshakeForAnotherVehicle_isRefused() {
        SecureEndpoint c = team.endpoint("uav-c");
        byte[] hello = a.startHandshake("uav-c");

        Unwrapped.Rejected r = refusedBy(b, hello, Rejection.NOT_FOR_ME);

        assertEquals("handshake from 'uav-a' is addressed to 'uav-c', not to 'uav-b'", r.detail());
        assertEquals("uav-c", c.id());
    }

    @Test
    void handshakeWithABadSignature_setsUpNothing() {
        byte[] hello = a.startHandshake("uav-b");
        hello[hello.length - 10] ^= 1;

        refusedBy(b, hello, Rejection.BAD_SIGNATURE);

        assertFalse(b.hasSession("uav-a"));
    }

    @Test
    void handshakeFromAnExpiredCredential_isRefused() {
        SecureEndpoint old = team.endpoint(team.identity("uav-old", T0 - 2 * HOUR, T0 - 1, MISSION, team.authority));

        refusedBy(b, old.startHandshake("uav-b"), Rejection.EXPIRED_CREDENTIAL);
    }

    @Test
    void replayedMacdMessage_isRefusedAsReplay() {
        Team.shakeHands(a, b);
        byte[] datagram = a.wrapFor("uav-b", heartbeat);
        assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(datagram));

        refusedBy(b, datagram, Rejection.REPLAY);
    }

    @Test
    void macdMessageOutsideTheFreshnessWindow_isRefusedAsStale() {
        Team.shakeHands(a, b);
        byte[] datagram = a.wrapFor("uav-b", heartbeat);
        team.clock.advance(30_001);

        refusedBy(b, datagram, Rejection.STALE);
    }

    @Test
    void validMacButAlteredBody_isRefusedAsBadMac_andNotDelivered() {
        Team.shakeHands(a, b);
        byte[] datagram = a.wrapFor("uav-b", heartbeat);
        byte[] genuine = datagram.clone();
        datagram[datagram.length - 16 - 3] ^= 0x01;   // a payload byte; the MAC is the original's

        Unwrapped.Rejected r = refusedBy(b, datagram, Rejection.BAD_MAC);

        assertEquals("pair-MAC datagram from 'uav-a': the MAC does not verify under the session key", r.detail());
        assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(genuine), "the genuine message still passes: nothing was spent");
    }

    @Test
    void alteredSenderId_isRefusedAsBadMac() {
        SecureEndpoint c = team.endpoint("uav-c");
        Team.shakeHands(a, b);
        Team.shakeHands(c, b);
        byte[] datagram = a.wrapFor("uav-b", heartbeat);
        datagram[2 + 1 + 4] = 'c';   // "uav-a" -> "uav-c"

        refusedBy(b, datagram, Rejection.BAD_MAC);
    }

    @Test
    void macdMessageReturnedToItsSender_isRefused() {
        Team.shakeHands(a, b);

        Unwrapped.Rejected r = refusedBy(a, a.wrapFor("uav-b", heartbeat), Rejection.NOT_FOR_ME);

        assertEquals("pair-MAC datagram from 'uav-a': claims this endpoint's own id; a reflection", r.detail());
    }

    @Test
    void macdMessageReflectedWithThePeersIdAsSender_isRefusedAsBadMac_forEachDirectionHasItsKey() {
        Team.shakeHands(a, b);
        byte[] fromB = b.wrapFor("uav-a", heartbeat);
        fromB[2 + 1 + 4] = 'a';   // "uav-b" -> "uav-a", then back to b

        refusedBy(b, fromB, Rejection.BAD_MAC);
    }

    @Test
    void macdMessageFromAVehicleWithoutSession_isRefusedAsUnknownSender_namingTheClaimedSender() {
        SecureEndpoint c = team.endpoint("uav-c");
        Team.shakeHands(c, a);

        Unwrapped.Rejected r = refusedBy(b, c.wrapFor("uav-a", heartbeat), Rejection.UNKNOWN_SENDER);

        assertEquals("uav-c", r.claimedSender());
    }

    @Test
    void sessionWhosePeerCredentialExpires_refusesItsMessages() {
        SecureEndpoint shortLived = team.endpoint(team.identity("uav-s", T0 - HOUR, T0 + 60_000, MISSION, team.authority));
        Team.shakeHands(shortLived, b);
        team.clock.advance(60_000);

        Unwrapped.Rejected r = refusedBy(b, shortLived.wrapFor("uav-b", heartbeat), Rejection.EXPIRED_CREDENTIAL);

        assertTrue(r.detail().startsWith("pair-MAC datagram from 'uav-s': credential expired at "), r.detail());
    }

    @Test
    void forget_dropsTheSession_andAFreshHandshakeRestoresIt() {
        Team.shakeHands(a, b);
        a.forget("uav-b");
        assertFalse(a.hasSession("uav-b"));
        assertTrue(a.needsHandshake("uav-b"));

        Team.shakeHands(a, b);

        assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(a.wrapFor("uav-b", heartbeat)));
    }

    @Test
    void wrapForAVehicleWithoutSession_failsNamingBoth() {
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> a.wrapFor("uav-b", heartbeat));

        assertEquals("'uav-a' has no session with 'uav-b' to wrap a payload for it; start a handshake first (startHandshake)", e.getMessage());
    }

    @Test
    void handshakeWithItself_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> a.startHandshake("uav-a"));

        assertEquals("'uav-a' cannot shake hands with itself", e.getMessage());
    }

    @Test
    void pairOverhead_is19BytesPlusTheSenderId() {
        Team.shakeHands(a, b);

        assertEquals(19 + "uav-a".length(), a.overhead(Protection.PAIR_MAC));
        assertEquals(heartbeat.length + 24, a.wrapFor("uav-b", heartbeat).length);
    }
}
