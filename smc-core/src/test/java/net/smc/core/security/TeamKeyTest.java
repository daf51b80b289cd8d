package net.smc.core.security;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import net.smc.core.security.Unwrapped.ControlEvent;
import org.junit.jupiter.api.Test;

/** The team key: handed out under a session, sealed; then team broadcasts under it. */
class TeamKeyTest {
    private final Team team = new Team(5);
    private final SecureEndpoint commander = team.endpoint("cmdr");
    private final SecureEndpoint b = team.endpoint("uav-b");
    private final SecureEndpoint c = team.endpoint("uav-c");
    private final byte[] status = "TEAM status: search sector 4".getBytes(StandardCharsets.UTF_8);

    private void handOut() {
        Team.shakeHands(commander, b);
        Team.shakeHands(commander, c);
        commander.newTeamKey();
        assertEquals(ControlEvent.TEAM_KEY_INSTALLED, assertInstanceOf(Unwrapped.Control.class, b.unwrap(commander.wrapTeamKey("uav-b"))).event());
        assertEquals(ControlEvent.TEAM_KEY_INSTALLED, assertInstanceOf(Unwrapped.Control.class, c.unwrap(commander.wrapTeamKey("uav-c"))).event());
    }

    private Unwrapped.Rejected refusedBy(SecureEndpoint to, byte[] datagram, Rejection reason) {
        String before = Team.state(to);
        Unwrapped.Rejected r = assertInstanceOf(Unwrapped.Rejected.class, to.unwrap(datagram));
        assertEquals(reason, r.reason(), r.detail());
        assertEquals(before, Team.state(to), "a refused datagram changes nothing");
        return r;
    }

    @Test
    void teamBroadcast_reachesEveryMember_withTheClaimedSender() {
        handOut();

        byte[] fromB = b.wrapTeam(status);
        Unwrapped.Delivered atC = assertInstanceOf(Unwrapped.Delivered.class, c.unwrap(fromB));
        Unwrapped.Delivered atCommander = assertInstanceOf(Unwrapped.Delivered.class, commander.unwrap(fromB));

        assertEquals("uav-b", atC.sender());
        assertEquals(Protection.TEAM_MAC, atC.protection());
        assertArrayEquals(status, atC.payload());
        assertArrayEquals(status, atCommander.payload());
    }

    @Test
    void teamKeyOnTheWire_isNotTheKey() {
        Team.shakeHands(commander, b);
        commander.newTeamKey();

        byte[] datagram = commander.wrapTeamKey("uav-b");

        assertFalse(indexOf(datagram, commander.team.key) >= 0, "the team key travels sealed");
        assertEquals(2 + 1 + 4 + 6 + 32 + 16, datagram.length);
    }

    @Test
    void alteredSealedTeamKey_isRefusedAsBadMac_andTheOldKeyStays() {
        handOut();
        int before = b.team.id;
        commander.newTeamKey();
        byte[] datagram = commander.wrapTeamKey("uav-b");
        datagram[datagram.length - 20] ^= 1;

        refusedBy(b, datagram, Rejection.BAD_MAC);

        assertEquals(before, b.team.id);
    }

    @Test
    void teamKeyFromAVehicleWithoutSession_isRefusedAsUnknownSender() {
        Team.shakeHands(commander, b);
        commander.newTeamKey();

        refusedBy(c, commander.wrapTeamKey("uav-b"), Rejection.UNKNOWN_SENDER);

        assertFalse(c.hasTeamKey());
    }

    @Test
    void teamKeySealedForAnotherMember_isRefusedAsBadMac() {
        Team.shakeHands(commander, b);
        Team.shakeHands(commander, c);
        commander.newTeamKey();

        refusedBy(c, commander.wrapTeamKey("uav-b"), Rejection.BAD_MAC);
    }

    @Test
    void replayedTeamKey_isRefusedAsReplay() {
        Team.shakeHands(commander, b);
        commander.newTeamKey();
        byte[] datagram = commander.wrapTeamKey("uav-b");
        b.unwrap(datagram);

        refusedBy(b, datagram, Rejection.REPLAY);
    }

    @Test
    void teamBroadcastWithoutTheTeamKey_isRefusedAsNoTeamKey() {
        Team.shakeHands(commander, b);
        commander.newTeamKey();

        Unwrapped.Rejected r = refusedBy(c, commander.wrapTeam(status), Rejection.NO_TEAM_KEY);

        assertTrue(r.detail().endsWith("but 'uav-c' holds no team key"), r.detail());
    }

    @Test
    void teamBroadcastUnderAnOldTeamKey_isRefusedAsNoTeamKey() {
        handOut();
        byte[] old = b.wrapTeam(status);
        commander.newTeamKey();
        c.unwrap(commander.wrapTeamKey("uav-c"));

        refusedBy(c, old, Rejection.NO_TEAM_KEY);
    }

    @Test
    void alteredTeamBroadcast_isRefusedAsBadMac() {
        handOut();
        byte[] datagram = b.wrapTeam(status);
        datagram[datagram.length - 17] ^= 1;

        refusedBy(c, datagram, Rejection.BAD_MAC);
    }

    @Test
    void replayedTeamBroadcast_isRefusedAsReplay_perSender() {
        handOut();
        byte[] fromB = b.wrapTeam(status);
        c.unwrap(fromB);

        refusedBy(c, fromB, Rejection.REPLAY);
        assertInstanceOf(Unwrapped.Delivered.class, c.unwrap(commander.wrapTeam(status)), "another sender's counters are its own");
    }

    @Test
    void staleTeamBroadcast_isRefusedAsStale() {
        handOut();
        byte[] fromB = b.wrapTeam(status);
        team.clock.advance(30_001);

        refusedBy(c, fromB, Rejection.STALE);
    }

    @Test
    void wrapTeamWithoutATeamKey_failsSayingHowToGetOne() {
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> b.wrapTeam(status));

        assertEquals("'uav-b' holds no team key: a commander makes one (newTeamKey) and sends it to members (wrapTeamKey)", e.getMessage());
    }

    @Test
    void teamOverhead_is23BytesPlusTheSenderId() {
        handOut();

        assertEquals(23 + "uav-b".length(), b.overhead(Protection.TEAM_MAC));
        assertEquals(status.length + 28, b.wrapTeam(status).length);
    }

    private static int indexOf(byte[] haystack, byte[] needle) {
        outer:
        for (int i = 0; i + needle.length <= haystack.length; i++) {
            for (int j = 0; j < needle.length; j++) {
                if (haystack[i + j] != needle[j]) {
                    continue outer;
                }
            }
            return i;
        }
        return -1;
    }
}
