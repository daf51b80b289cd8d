package net.smc.core.security;

import static net.smc.core.security.Team.HOUR;
import static net.smc.core.security.Team.T0;
import static org.junit.jupiter.api.Assertions.assertEquals;

import net.smc.core.transport.Address;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.SimulationScheduler;
import org.junit.jupiter.api.Test;

/**
 * Ideal authentication verifies a credential's signature once per JVM: the same credential shown
 * again, to any instance, is still judged on its validity period, its mission and its authority.
 */
class IdealCredentialCheckTest {
    private final Team team = new Team(11);
    private int port = 4100;

    private CredentialStatus wrapAt(long nowMillis, TrustAnchor trust, Credential credential) {
        SimulationScheduler scheduler = new SimulationScheduler(nowMillis);
        InMemoryNetwork network = new InMemoryNetwork(scheduler, 1);
        IdealAuthentication ideal = new IdealAuthentication(trust, scheduler);
        return ideal.wrap(network.attach(Address.loopback(port++)), credential).credentialStatus();
    }

    @Test
    void aCredentialVerifiedOnce_isStillCheckedForTimeMissionAndAuthority() {
        Credential credential = team.identity("uav-a").credential();
        assertEquals(CredentialStatus.VALID, wrapAt(T0, team.trust, credential));
        assertEquals(CredentialStatus.VALID, wrapAt(T0, team.trust, credential));

        assertEquals(CredentialStatus.EXPIRED, wrapAt(T0 + 25 * HOUR, team.trust, credential));
        assertEquals(CredentialStatus.NOT_YET_VALID, wrapAt(T0 - 2 * HOUR, team.trust, credential));
        assertEquals(CredentialStatus.WRONG_MISSION,
                wrapAt(T0, new TrustAnchor(team.authority.verificationKey(), "another-mission"), credential));
        SigningKey other = SigningKey.generate(Team.seeded(12));
        assertEquals(CredentialStatus.FOREIGN_AUTHORITY,
                wrapAt(T0, new TrustAnchor(other.verificationKey(), Team.MISSION), credential));
    }

    @Test
    void aBadSignature_isRefusedEveryTime() {
        Credential good = team.identity("uav-b").credential();
        byte[] signature = good.signature();
        signature[0] ^= 1;
        Credential forged = new Credential(good.claims(), good.authority(), signature);
        assertEquals(CredentialStatus.VALID, wrapAt(T0, team.trust, good));
        assertEquals(CredentialStatus.BAD_SIGNATURE, wrapAt(T0, team.trust, forged));
        assertEquals(CredentialStatus.BAD_SIGNATURE, wrapAt(T0, team.trust, forged));
    }
}
