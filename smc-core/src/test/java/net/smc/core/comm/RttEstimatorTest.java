package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import net.smc.core.transport.Address;

class RttEstimatorTest {
    /** Initial (ceiling) 200 ms, minimum (floor) 5 ms. */
    private static final SenderSettings ADAPTIVE = new SenderSettings(200, 2.0, 1_000, 4, 0.0, 60_000, 100, 5);
    private static final Address B = Address.loopback(4002);
    private static final Address C = Address.loopback(4003);

    private final RttEstimator rtt = new RttEstimator(ADAPTIVE);

    @Test
    void nothingMeasured_givesTheInitialTimeout() {
        assertEquals(200, rtt.timeoutMillis(B));
        assertEquals(200, rtt.cellTimeoutMillis());
        assertTrue(Double.isNaN(rtt.smoothedRttMillis(B)));
        assertEquals(0, rtt.peers());
    }

    @Test
    void peerWithoutSample_getsTheCellsEstimateOverItsOtherPeers() {
        rtt.sample(B, 10);
        rtt.sample(C, 14);
        // cell: srtt 10 -> 7/8 * 10 + 1/8 * 14 = 10.5; rttvar 5 -> 3/4 * 5 + 1/4 * 4 = 4.75: 10.5 + 19 = 29.5
        assertEquals(30, rtt.cellTimeoutMillis());
        Address d = Address.loopback(4004);
        assertEquals(30, rtt.timeoutMillis(d), "never measured: the cell's estimate");
        assertTrue(Double.isNaN(rtt.smoothedRttMillis(d)));
        assertEquals(30, rtt.timeoutMillis(B), "measured: its own, 10 + 4 * 5");
    }

    @Test
    void firstTryTimeout_leavesTheCellsEstimateAlone() {
        rtt.sample(B, 10);
        rtt.timedOut(B);
        assertEquals(60, rtt.timeoutMillis(B));
        assertEquals(30, rtt.cellTimeoutMillis());
    }

    @Test
    void firstSample_setsSrttToIt_andVariationToHalfOfIt() {
        rtt.sample(B, 20);
        assertEquals(20.0, rtt.smoothedRttMillis(B));
        assertEquals(10.0, rtt.rttVariationMillis(B));
        assertEquals(20 + 4 * 10, rtt.timeoutMillis(B));
    }

    @Test
    void laterSamples_areSmoothedWithGainsOneEighthAndOneQuarter() {
        rtt.sample(B, 20);
        rtt.sample(B, 36);
        // rttvar = 3/4 * 10 + 1/4 * |20 - 36| = 11.5; srtt = 7/8 * 20 + 1/8 * 36 = 22
        assertEquals(11.5, rtt.rttVariationMillis(B), 1e-9);
        assertEquals(22.0, rtt.smoothedRttMillis(B), 1e-9);
        assertEquals(22 + 46, rtt.timeoutMillis(B));
    }

    @Test
    void steadyRoundTrips_bringTheTimeoutDownToJustOverTheRoundTrip() {
        for (int i = 0; i < 100; i++) {
            rtt.sample(B, 12);
        }
        assertEquals(12.0, rtt.smoothedRttMillis(B), 1e-6);
        assertEquals(13, rtt.timeoutMillis(B), "srtt plus the 1 ms clock granularity once the variation is gone");
    }

    @Test
    void timeout_isClampedToTheMinimumAndTheInitialTimeout() {
        rtt.sample(B, 1);
        for (int i = 0; i < 50; i++) {
            rtt.sample(B, 1);
        }
        assertEquals(5, rtt.timeoutMillis(B), "floor");
        rtt.sample(C, 150);
        assertEquals(200, rtt.timeoutMillis(C), "150 + 4 * 75 is over the ceiling");
    }

    @Test
    void peers_areEstimatedIndependently() {
        rtt.sample(B, 10);
        rtt.sample(C, 40);
        rtt.sample(C, 60);
        assertEquals(10.0, rtt.smoothedRttMillis(B));
        assertEquals(30, rtt.timeoutMillis(B));
        assertEquals(42.5, rtt.smoothedRttMillis(C), 1e-9);
        assertEquals(2, rtt.peers());
        rtt.timedOut(C);
        assertEquals(30, rtt.timeoutMillis(B), "a timeout to one peer leaves the other alone");
    }

    @Test
    void firstTryTimeout_doublesThePeersTimeoutUpToTheCeiling_untilTheNextSample() {
        rtt.sample(B, 10); // timeout 30
        rtt.timedOut(B);
        assertEquals(60, rtt.timeoutMillis(B));
        rtt.timedOut(B);
        rtt.timedOut(B);
        assertEquals(200, rtt.timeoutMillis(B), "240 clamped to the initial timeout");
        rtt.sample(B, 10);
        assertEquals(10.0, rtt.smoothedRttMillis(B), 1e-9);
        assertEquals(10 + 4 * 3.75, rtt.timeoutMillis(B), 1e-9, "a sample recomputes the timeout");
    }

    @Test
    void timedOut_withoutSample_keepsTheInitialTimeout() {
        rtt.timedOut(B);
        assertEquals(200, rtt.timeoutMillis(B));
    }

    @Test
    void negativeRoundTrip_isRefusedNamingThePeer() {
        var e = assertThrows(IllegalArgumentException.class, () -> rtt.sample(B, -1));
        assertTrue(e.getMessage().contains(B.toString()) && e.getMessage().contains("negative"), e.getMessage());
    }
}
