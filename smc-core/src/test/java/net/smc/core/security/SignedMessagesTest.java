package net.smc.core.security;

import static net.smc.core.security.Team.HOUR;
import static net.smc.core.security.Team.MISSION;
import static net.smc.core.security.Team.T0;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import net.smc.core.transport.Transport;
import org.junit.jupiter.api.Test;

/**
 * Signed datagrams (discovery, first replies): each attack is refused, counted under its reason,
 * not delivered, and leaves the receiver as it was.
 */
class SignedMessagesTest {
    private final Team team = new Team(3);
    private final SecureEndpoint commander = team.endpoint("cmdr");
    private final SecureEndpoint vehicle = team.endpoint("uav-1");
    private final byte[] discovery = "DISCOVERY".getBytes(StandardCharsets.UTF_8);

    /** Unwraps at the vehicle, expecting a refusal for {@code reason} that changes nothing. */
    private Unwrapped.Rejected refused(byte[] datagram, Rejection reason) {
        String before = Team.state(vehicle);
        long countedBefore = vehicle.counters().rejected(reason);

        Unwrapped u = vehicle.unwrap(datagram);

        Unwrapped.Rejected r = assertInstanceOf(Unwrapped.Rejected.class, u, "should be refused: " + u);
        assertEquals(reason, r.reason(), r.detail());
        assertEquals(countedBefore + 1, vehicle.counters().rejected(reason));
        assertEquals(before, Team.state(vehicle), "a refused datagram changes nothing");
        return r;
    }

    @Test
    void signedDatagram_isDelivered_withItsSender() {
        Unwrapped u = vehicle.unwrap(commander.wrapSigned(discovery));

        Unwrapped.Delivered d = assertInstanceOf(Unwrapped.Delivered.class, u);
        assertEquals("cmdr", d.sender());
        assertEquals(Protection.SIGNED, d.protection());
        assertArrayEquals(discovery, d.payload());
        assertEquals(commander.identity.credential(), vehicle.credentialOf("cmdr").orElseThrow());
    }

    @Test
    void forgedSignature_isRefusedAsBadSignature() {
        byte[] datagram = commander.wrapSigned(discovery);
        datagram[datagram.length - 1] ^= 1;

        Unwrapped.Rejected r = refused(datagram, Rejection.BAD_SIGNATURE);

        assertEquals("signed datagram from 'cmdr': the signature does not verify with the key of its credential", r.detail());
    }

    @Test
    void alteredPayload_underAValidSignature_isRefusedAsBadSignature() {
        byte[] datagram = commander.wrapSigned(discovery);
        datagram[datagram.length - 64 - 1] ^= 0x20;

        refused(datagram, Rejection.BAD_SIGNATURE);
    }

    @Test
    void stolenCredential_signedWithAnotherKey_isRefusedAsBadSignature() {
        SigningKey thiefKey = SigningKey.generate(team.random);
        byte[] datagram = commander.wrapSigned(discovery);
        int n = datagram.length - 64;
        System.arraycopy(thiefKey.sign(datagram, 0, n), 0, datagram, n, 64);

        refused(datagram, Rejection.BAD_SIGNATURE);
    }

    @Test
    void credentialWithForgedClaims_isRefusedAsBadSignature() {
        SigningKey forgerKey = SigningKey.generate(team.random);
        Credential genuine = commander.identity.credential();
        Credential forged = new Credential(new Claims("cmdr", forgerKey.verificationKey(), MISSION, T0 - HOUR, T0 + HOUR),
                genuine.authority(), genuine.signature());
        SecureEndpoint forger = SecureEndpoint.builder(new SigningIdentity(forgerKey, forged), team.trust, team.clock).build();

        Unwrapped.Rejected r = refused(forger.wrapSigned(discovery), Rejection.BAD_SIGNATURE);

        assertEquals("signed datagram from 'cmdr': the authority's signature of its credential does not verify", r.detail());
    }

    @Test
    void credentialFromAnotherAuthority_isRefusedAsForeignAuthority() {
        SigningKey otherAuthority = SigningKey.generate(team.random);
        SecureEndpoint stranger = team.endpoint(team.identity("uav-9", T0 - HOUR, T0 + HOUR, MISSION, otherAuthority));

        Unwrapped.Rejected r = refused(stranger.wrapSigned(discovery), Rejection.FOREIGN_AUTHORITY);

        assertEquals("signed datagram from 'uav-9': credential issued by authority " + otherAuthority.verificationKey().id()
                + "; this vehicle trusts " + team.authority.verificationKey().id(), r.detail());
    }

    @Test
    void expiredCredential_isRefusedAsExpired() {
        SecureEndpoint old = team.endpoint(team.identity("uav-2", T0 - 2 * HOUR, T0 - HOUR, MISSION, team.authority));

        Unwrapped.Rejected r = refused(old.wrapSigned(discovery), Rejection.EXPIRED_CREDENTIAL);

        assertEquals("signed datagram from 'uav-2': credential expired at " + (T0 - HOUR) + " ms; the clock says " + T0 + " ms", r.detail());
    }

    @Test
    void credentialNotYetValid_isRefused() {
        SecureEndpoint early = team.endpoint(team.identity("uav-2", T0 + HOUR, T0 + 2 * HOUR, MISSION, team.authority));

        refused(early.wrapSigned(discovery), Rejection.CREDENTIAL_NOT_YET_VALID);
    }

    @Test
    void credentialForAnotherMission_isRefused() {
        SecureEndpoint other = team.endpoint(team.identity("uav-2", T0 - HOUR, T0 + HOUR, "survey", team.authority));

        Unwrapped.Rejected r = refused(other.wrapSigned(discovery), Rejection.WRONG_MISSION);

        assertEquals("signed datagram from 'uav-2': credential for mission 'survey'; this vehicle trusts only 'rescue'", r.detail());
    }

    @Test
    void replayedDatagram_isRefusedAsReplay() {
        byte[] datagram = commander.wrapSigned(discovery);
        assertInstanceOf(Unwrapped.Delivered.class, vehicle.unwrap(datagram));

        Unwrapped.Rejected r = refused(datagram, Rejection.REPLAY);

        assertTrue(r.detail().startsWith("signed datagram from 'cmdr': counter "), r.detail());
    }

    @Test
    void reorderedDatagrams_areBothDelivered() {
        byte[] first = commander.wrapSigned(discovery);
        byte[] second = commander.wrapSigned(discovery);

        assertInstanceOf(Unwrapped.Delivered.class, vehicle.unwrap(second));
        assertInstanceOf(Unwrapped.Delivered.class, vehicle.unwrap(first));
    }

    @Test
    void datagramOlderThanTheFreshnessWindow_isRefusedAsStale() {
        byte[] datagram = commander.wrapSigned(discovery);
        team.clock.advance(30_001);

        Unwrapped.Rejected r = refused(datagram, Rejection.STALE);

        assertEquals("signed datagram from 'cmdr': timestamp " + T0 + " ms is 30001 ms behind the clock (" + (T0 + 30_001)
                + " ms); the freshness window is 30000 ms either way", r.detail());
    }

    @Test
    void datagramFromTheFuture_isRefusedAsStale() {
        team.clock.advance(30_001);
        byte[] datagram = commander.wrapSigned(discovery);
        team.clock.advance(-30_001);

        Unwrapped.Rejected r = refused(datagram, Rejection.STALE);

        assertTrue(r.detail().contains("is 30001 ms ahead of the clock"), r.detail());
    }

    @Test
    void datagramAtTheEdgeOfTheWindow_isDelivered() {
        byte[] datagram = commander.wrapSigned(discovery);
        team.clock.advance(30_000);

        assertInstanceOf(Unwrapped.Delivered.class, vehicle.unwrap(datagram));
    }

    @Test
    void ownDatagramReflected_isRefused() {
        Unwrapped.Rejected r = refused(vehicle.wrapSigned(discovery), Rejection.NOT_FOR_ME);

        assertEquals("signed datagram from 'uav-1': carries this endpoint's own credential; a reflection", r.detail());
    }

    @Test
    void forgedDatagram_withAHighCounter_doesNotAdvanceTheWindow() {
        byte[] genuine = commander.wrapSigned(discovery);
        byte[] later = commander.wrapSigned(discovery);
        later[later.length - 1] ^= 1;

        refused(later, Rejection.BAD_SIGNATURE);

        assertInstanceOf(Unwrapped.Delivered.class, vehicle.unwrap(genuine));
    }

    @Test
    void restartedSender_countsAboveItsFormerSelf() {
        assertInstanceOf(Unwrapped.Delivered.class, vehicle.unwrap(commander.wrapSigned(discovery)));
        team.clock.advance(1);
        SecureEndpoint restarted = team.endpoint(commander.identity);

        assertInstanceOf(Unwrapped.Delivered.class, vehicle.unwrap(restarted.wrapSigned(discovery)));
    }

    @Test
    void signedOverhead_isHeaderCredentialAndSignature() {
        int credential = 123 + "cmdr".length() + MISSION.length();

        assertEquals(2 + 6 + 1 + credential + 64, commander.overhead(Protection.SIGNED));
        assertEquals(commander.wrapSigned(discovery).length, discovery.length + commander.overhead(Protection.SIGNED));
    }

    @Test
    void payloadThatNoLongerFits_isRefused_sayingTheLimit() {
        int max = commander.maxPayload(Protection.SIGNED);
        assertEquals(Transport.MAX_DATAGRAM_BYTES, commander.wrapSigned(new byte[max]).length);

        PayloadTooLargeException e = assertThrows(PayloadTooLargeException.class, () -> commander.wrapSigned(new byte[max + 1]));

        assertEquals("payload of " + (max + 1) + " bytes does not fit a SIGNED datagram: the envelope adds "
                + commander.overhead(Protection.SIGNED) + " bytes and a datagram may carry at most 1400, so the payload may be at most "
                + max + " bytes", e.getMessage());
        assertEquals(max, e.limit());
    }
}
