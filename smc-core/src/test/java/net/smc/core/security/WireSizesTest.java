package net.smc.core.security;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

import org.junit.jupiter.api.Test;

/** The sizes a model charges are those of the datagrams the endpoint makes. */
class WireSizesTest {
    private final Team team = new Team(7);

    @Test
    void signedPairMacAndHello_measureWhatTheEndpointMakes() {
        for (String[] names : new String[][] {{"uav-1", "uav-22"}, {"b0l3n17", "cdr"}, {"véhicule-é", "x"}}) {
            SecureEndpoint a = team.endpoint(names[0]);
            SecureEndpoint b = team.endpoint(names[1]);
            for (int payload : new int[] {0, 1, 57, 900}) {
                assertEquals(a.wrapSigned(new byte[payload]).length, WireSizes.signed(names[0], Team.MISSION, payload));
            }
            byte[] hello = a.startHandshake(names[1]);
            assertEquals(hello.length, WireSizes.hello(names[0], Team.MISSION, names[1]));
            Unwrapped offered = b.unwrap(hello);
            byte[] answer = assertInstanceOf(Unwrapped.Control.class, offered).reply();
            assertEquals(answer.length, WireSizes.hello(names[1], Team.MISSION, names[0]));
            Team.shakeHands(a, b);
            for (int payload : new int[] {0, 40, 1_000}) {
                assertEquals(a.wrapFor(names[1], new byte[payload]).length, WireSizes.pairMac(names[0], payload));
            }
        }
    }

    @Test
    void aCredentialIs123BytesAndItsNames() {
        assertEquals(123 + 5 + 6, WireSizes.credential("uav-1", "rescue"));
        assertEquals(team.identity("uav-1").credential().encode().length, WireSizes.credential("uav-1", Team.MISSION));
    }
}
