package net.smc.core.transport.sim;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.BooleanSupplier;

import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;
import net.smc.core.transport.TransportContract;

/** The transport contract on the in-memory network, with the default 1 ms fault-free links. */
class InMemoryTransportContractTest extends TransportContract {

    @Override
    protected Net newNet() {
        SimulationScheduler scheduler = new SimulationScheduler();
        InMemoryNetwork network = new InMemoryNetwork(scheduler, 1);
        return new Net() {
            private int nextPort = 4001;

            @Override
            public Transport open() {
                return network.attach(Address.loopback(nextPort++));
            }

            @Override
            public void awaitUntil(BooleanSupplier done) {
                assertTrue(scheduler.runUntil(done, scheduler.nowMillis() + 60_000),
                        "condition not met in 60 s of simulated time");
            }

            @Override
            public void close() {
            }
        };
    }
}
