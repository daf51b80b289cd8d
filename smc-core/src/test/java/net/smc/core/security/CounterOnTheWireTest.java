package net.smc.core.security;

import static net.smc.core.security.Team.HOUR;
import static net.smc.core.security.Team.MISSION;
import static net.smc.core.security.Team.T0;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/**
 * The counter travels as its low 48 bits and is found again near the receiver's clock; the tags
 * cover it in full, so the same low bits a wrap later do not pass.
 */
class CounterOnTheWireTest {
    private static final long WRAP = 1L << 48;
    /** The time after which a counter's low 48 bits repeat: 2^48 counter steps of 2^-20 ms. */
    private static final long WRAP_MILLIS = WRAP >> SecureEndpoint.COUNTER_SHIFT;
    private static final long WEEK = 7 * 24 * HOUR;

    private final Team team = new Team(11);
    private final SecureEndpoint a = team.endpoint(longLived("uav-a"));
    private final SecureEndpoint b = team.endpoint(longLived("uav-b"));
    private final byte[] payload = "status v=3".getBytes(StandardCharsets.UTF_8);

    private SigningIdentity longLived(String id) {
        return team.identity(id, T0 - HOUR, T0 + WEEK, MISSION, team.authority);
    }

    @Test
    void counterNear_findsTheCounterWithThoseLowBits_nearestTheReference() {
        long counter = T0 << SecureEndpoint.COUNTER_SHIFT;
        long low = counter & (WRAP - 1);

        assertEquals(counter, FrameCodec.counterNear(low, counter));
        assertEquals(counter, FrameCodec.counterNear(low, counter + (WRAP / 2 - 1)), "reference just under half a wrap ahead");
        assertEquals(counter, FrameCodec.counterNear(low, counter - (WRAP / 2 - 1)), "reference just under half a wrap behind");
        assertEquals(counter + WRAP, FrameCodec.counterNear(low, counter + WRAP - 5), "a wrap later the same bits name a later counter");
    }

    @Test
    void counterNear_crossesA48BitBoundary_eitherWay() {
        long boundary = 5 * WRAP;

        assertEquals(boundary - 3, FrameCodec.counterNear(WRAP - 3, boundary + 10), "sent just before the boundary, read just after");
        assertEquals(boundary + 3, FrameCodec.counterNear(3, boundary - 10), "sent just after the boundary, read just before");
    }

    @Test
    void wireCarriesSixBytesOfCounter_andTheReceiverRecoversTheSendersTime() {
        Team.shakeHands(a, b);
        team.clock.advance(12_345);
        byte[] datagram = a.wrapFor("uav-b", payload);

        int counterAt = 2 + 1 + "uav-a".length();
        long onWire = 0;
        for (int i = 0; i < FrameCodec.COUNTER_BYTES; i++) {
            onWire = onWire << 8 | datagram[counterAt + i] & 0xFF;
        }
        team.clock.advance(29_000);
        Frame.Keyed frame = (Frame.Keyed) assertDoesNotThrowRead(datagram, b);

        assertEquals(frame.counter() & (WRAP - 1), onWire, "the wire holds the counter's low 48 bits");
        assertEquals(T0 + 12_345, frame.timestampMillis(), "the counter's time is the sender's clock when it sent");
        assertArrayEquals(payload, assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(datagram)).payload());
    }

    @Test
    void widestFreshnessWindow_stillFindsTheCounter() {
        SecuritySettings day = new SecuritySettings(24 * HOUR, 64, 1_000);
        SecureEndpoint sender = SecureEndpoint.builder(longLived("uav-c"), team.trust, team.clock).random(team.random).build();
        SecureEndpoint receiver = SecureEndpoint.builder(longLived("uav-d"), team.trust, team.clock).random(team.random)
                .settings(day).build();
        byte[] datagram = sender.wrapSigned(payload);
        team.clock.advance(24 * HOUR - 1);

        assertInstanceOf(Unwrapped.Delivered.class, receiver.unwrap(datagram), "a day late, still within the window");
    }

    @Test
    void macdDatagramReplayedAWrapLater_isRefusedAsBadMac_thoughItsLowBitsNameAFreshCounter() {
        Team.shakeHands(a, b);
        Unwrapped.Rejected r = replayedAWrapLater(a.wrapFor("uav-b", payload));
        assertEquals(Rejection.BAD_MAC, r.reason(), r.detail());
    }

    @Test
    void signedDatagramReplayedAWrapLater_isRefusedAsBadSignature() {
        Unwrapped.Rejected r = replayedAWrapLater(a.wrapSigned(payload));
        assertEquals(Rejection.BAD_SIGNATURE, r.reason(), r.detail());
    }

    /** Delivers {@code datagram} to b, replays it 2^48 counter steps later, and returns b's refusal. */
    private Unwrapped.Rejected replayedAWrapLater(byte[] datagram) {
        assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(datagram));
        team.clock.advance(WRAP_MILLIS);
        return assertInstanceOf(Unwrapped.Rejected.class, b.unwrap(datagram));
    }

    @Test
    void counterBitsAltered_areRefusedAsBadMac() {
        Team.shakeHands(a, b);
        byte[] datagram = a.wrapFor("uav-b", payload);
        datagram[2 + 1 + "uav-a".length() + FrameCodec.COUNTER_BYTES - 1] ^= 1;

        Unwrapped.Rejected r = assertInstanceOf(Unwrapped.Rejected.class, b.unwrap(datagram));

        assertEquals(Rejection.BAD_MAC, r.reason(), r.detail());
    }

    private static Frame assertDoesNotThrowRead(byte[] datagram, SecureEndpoint receiver) {
        try {
            return FrameCodec.read(datagram, receiver.referenceCounter());
        } catch (Malformed m) {
            throw new AssertionError("a genuine datagram parses: " + m.getMessage(), m);
        }
    }
}
