package net.smc.core.transport.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;

class NetworkCpuChargeTest {
    private final SimulationScheduler scheduler = new SimulationScheduler();
    private final InMemoryNetwork network = new InMemoryNetwork(scheduler, 1);
    private final Address a = Address.loopback(1);
    private final Address b = Address.loopback(2);
    private final Transport ta = network.attach(a);
    private final Transport tb = network.attach(b);
    private final List<Long> arrivals = new ArrayList<>();

    NetworkCpuChargeTest() {
        network.setDefaultLink(LinkProfile.fixed(1));
        tb.setReceiver((from, data) -> arrivals.add(scheduler.nowMillis()));
        ta.setReceiver((from, data) -> { });
    }

    private static CpuModel costs(long sendMicros, long receiveMicros) {
        return new CpuModel() {
            @Override
            public long sendMicros(Address at, Address to, byte[] data) {
                return sendMicros;
            }

            @Override
            public long receiveMicros(Address at, Address from, byte[] data, boolean broadcast) {
                return receiveMicros;
            }
        };
    }

    @Test
    void busyCell_handlesItsNextDatagramOnlyWhenFree() {
        network.setCpuModel(costs(0, 5_000));
        for (int i = 0; i < 3; i++) {
            ta.send(b, new byte[] {1});
        }
        scheduler.runUntil(100);
        assertEquals(List.of(6L, 11L, 16L), arrivals);
        assertEquals(15_000, network.cpuMicros(b));
    }

    @Test
    void costsBelowOneMillisecond_addUpWithoutRounding() {
        network.setCpuModel(costs(0, 300));
        for (int i = 0; i < 10; i++) {
            ta.send(b, new byte[] {1});
        }
        scheduler.runUntil(100);
        assertEquals(10, arrivals.size());
        assertEquals(4L, arrivals.get(9));   // arrives at 1 ms; 10 x 0.3 ms ends at 4 ms
    }

    @Test
    void sendingCosts_delayDeparture_andBandwidthSerialises() {
        network.setCpuModel(costs(2_000, 0));
        network.setBandwidth(1_000);   // 1 byte per ms
        ta.send(b, new byte[10]);
        ta.send(b, new byte[10]);
        scheduler.runUntil(100);
        // first: CPU until 2 ms, on air 2..12, arrives 13; second: CPU until 4, waits for the radio, 12..22, arrives 23
        assertEquals(List.of(13L, 23L), arrivals);
    }

    @Test
    void withoutModel_datagramsArriveAfterLatencyOnly() {
        ta.send(b, new byte[] {1});
        ta.send(b, new byte[] {1});
        scheduler.runUntil(10);
        assertEquals(List.of(1L, 1L), arrivals);
        assertTrue(network.cpuMicros(b) == 0);
    }

    @Test
    void bandwidthWithoutModel_isRefused() {
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> network.setBandwidth(1_000));
        assertTrue(e.getMessage().contains("needs a CPU model"), e.getMessage());
        IllegalArgumentException n = assertThrows(IllegalArgumentException.class, () -> network.setBandwidth(-1));
        assertTrue(n.getMessage().contains("negative"), n.getMessage());
    }
}
