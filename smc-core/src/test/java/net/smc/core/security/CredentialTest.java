package net.smc.core.security;

import static net.smc.core.security.Team.HOUR;
import static net.smc.core.security.Team.MISSION;
import static net.smc.core.security.Team.T0;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

class CredentialTest {
    private final Team team = new Team(1);
    private final SigningKey vehicle = SigningKey.generate(team.random);

    private Claims claims(String id, String mission) {
        return new Claims(id, vehicle.verificationKey(), mission, T0, T0 + HOUR);
    }

    @Test
    void issuedCredential_verifiesWithinItsValidity() {
        Credential c = Credential.issue(claims("uav-1", MISSION), team.authority);

        assertEquals(CredentialStatus.VALID, team.trust.verify(c, T0));
        assertEquals(CredentialStatus.VALID, team.trust.verify(c, T0 + HOUR - 1));
        assertEquals(team.authority.verificationKey().id(), c.authority());
    }

    @Test
    void expiredCredential_isExpired_atAndAfterItsExpiry() {
        Credential c = Credential.issue(claims("uav-1", MISSION), team.authority);

        assertEquals(CredentialStatus.EXPIRED, team.trust.verify(c, T0 + HOUR));
    }

    @Test
    void credentialBeforeItsNotBefore_isNotYetValid() {
        Credential c = Credential.issue(claims("uav-1", MISSION), team.authority);

        assertEquals(CredentialStatus.NOT_YET_VALID, team.trust.verify(c, T0 - 1));
    }

    @Test
    void credentialOfAnotherAuthority_isForeign() {
        SigningKey other = SigningKey.generate(team.random);
        Credential c = Credential.issue(claims("uav-1", MISSION), other);

        assertEquals(CredentialStatus.FOREIGN_AUTHORITY, team.trust.verify(c, T0));
    }

    @Test
    void alteredClaims_haveABadSignature() {
        Credential c = Credential.issue(claims("uav-1", MISSION), team.authority);
        Credential altered = new Credential(new Claims("uav-1", vehicle.verificationKey(), MISSION, T0, T0 + 100 * HOUR),
                c.authority(), c.signature());

        assertEquals(CredentialStatus.BAD_SIGNATURE, team.trust.verify(altered, T0));
    }

    @Test
    void credentialForAnotherMission_isWrongMission_butAnyMissionTrustAcceptsIt() {
        Credential c = Credential.issue(claims("uav-1", "survey"), team.authority);

        assertEquals(CredentialStatus.WRONG_MISSION, team.trust.verify(c, T0));
        assertEquals(CredentialStatus.VALID, TrustAnchor.of(team.authority.verificationKey()).verify(c, T0));
    }

    @Test
    void encoding_roundTrips_andIsCompact() throws Exception {
        Credential c = Credential.issue(claims("uav-1", MISSION), team.authority);

        byte[] encoded = c.encode();

        assertEquals(c, Credential.decode(encoded));
        assertEquals(123 + "uav-1".length() + MISSION.length(), encoded.length);
        assertEquals(CredentialStatus.VALID, team.trust.verify(Credential.decode(encoded), T0));
    }

    @Test
    void longestNames_encodeWithin251Bytes() {
        Credential c = Credential.issue(claims("v".repeat(64), "m".repeat(64)), team.authority);

        assertEquals(251, c.encode().length);
    }

    @Test
    void oversizeVehicleId_isRefused_namingTheFieldAndTheLimit() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> claims("v".repeat(65), MISSION));

        assertEquals("credential: vehicle id '" + "v".repeat(65) + "' is 65 bytes of UTF-8; the limit is 64", e.getMessage());
    }

    @Test
    void oversizeMission_countsUtf8Bytes() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> claims("uav-1", "é".repeat(33)));

        assertTrue(e.getMessage().startsWith("credential: mission '") && e.getMessage().endsWith("is 66 bytes of UTF-8; the limit is 64"),
                e.getMessage());
    }

    @Test
    void emptyVehicleId_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> claims("", MISSION));

        assertEquals("credential: vehicle id is empty; it must have 1 to 64 bytes of UTF-8", e.getMessage());
    }

    @Test
    void expiryNotAfterNotBefore_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Claims("uav-1", vehicle.verificationKey(), MISSION, T0, T0));

        assertTrue(e.getMessage().contains("it must expire after it becomes valid"), e.getMessage());
    }

    @Test
    void decode_refusesAnUnknownVersion() {
        byte[] encoded = Credential.issue(claims("uav-1", MISSION), team.authority).encode();
        encoded[0] = 2;

        CredentialFormatException e = assertThrows(CredentialFormatException.class, () -> Credential.decode(encoded));

        assertEquals("credential: version at byte 0: 2 is not a known version; this reader knows 1", e.getMessage());
    }

    @Test
    void decode_refusesEveryTruncation_namingTheField() {
        byte[] encoded = Credential.issue(claims("uav-1", MISSION), team.authority).encode();

        for (int n = 0; n < encoded.length; n++) {
            byte[] cut = Arrays.copyOf(encoded, n);
            CredentialFormatException e = assertThrows(CredentialFormatException.class, () -> Credential.decode(cut));
            assertTrue(e.getMessage().startsWith("credential: "), e.getMessage());
        }
    }

    @Test
    void decode_refusesTrailingBytes() {
        byte[] encoded = Arrays.copyOf(Credential.issue(claims("uav-1", MISSION), team.authority).encode(), 135);

        CredentialFormatException e = assertThrows(CredentialFormatException.class, () -> Credential.decode(encoded));

        assertEquals("credential: end at byte 134: 1 bytes after the signature; a credential ends with it", e.getMessage());
    }

    @Test
    void decode_refusesALengthOverTheLimit() {
        byte[] encoded = Credential.issue(claims("uav-1", MISSION), team.authority).encode();
        encoded[1] = 65;

        CredentialFormatException e = assertThrows(CredentialFormatException.class, () -> Credential.decode(encoded));

        assertEquals("credential: vehicle id at byte 1: length 65; it must be 1 to 64", e.getMessage());
    }

    @Test
    void identity_refusesACredentialForAnotherKey() {
        Credential c = Credential.issue(claims("uav-1", MISSION), team.authority);
        SigningKey other = SigningKey.generate(team.random);

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new SigningIdentity(other, c));

        assertTrue(e.getMessage().startsWith("credential of 'uav-1' is for key " + vehicle.verificationKey().id()), e.getMessage());
    }
}
