package net.smc.core.transport;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;

import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.SimulationScheduler;

import org.junit.jupiter.api.Test;

/** The example of this package's javadoc, as written there. */
class PackageExampleTest {

    @Test
    void aSimulatedPairOfCells_talk() {
        SimulationScheduler scheduler = new SimulationScheduler();
        InMemoryNetwork network = new InMemoryNetwork(scheduler, 42);
        Transport a = network.attach(Address.loopback(4001)), b = network.attach(Address.loopback(4002));
        List<String> heard = new ArrayList<>();
        b.setReceiver((from, data) -> heard.add(from + " says " + new String(data)));
        a.send(b.localAddress(), "hello".getBytes());  scheduler.runUntilIdle(1_000);

        assertEquals(List.of("127.0.0.1:4001 says hello"), heard);
    }
}
