package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import java.util.function.BooleanSupplier;

import net.smc.core.transport.Address;
import net.smc.core.transport.Signal;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.LinkProfile;
import net.smc.core.transport.sim.SimulationScheduler;

/** Cells on the in-memory network, on virtual time: one thread, deterministic per seed. */
final class SimNet implements Net {
    final SimulationScheduler scheduler = new SimulationScheduler();
    final InMemoryNetwork network;
    private final SenderSettings settings;
    private final SplittableRandom seeds;
    private final Signal signal = new Signal();
    private int nextPort = 4001;

    SimNet(Faults faults, long seed, SenderSettings settings) {
        this.settings = settings;
        this.network = new InMemoryNetwork(scheduler, seed);
        this.seeds = new SplittableRandom(seed);
        network.setDefaultLink(LinkProfile.fixed(5).withLatency(5, 5).withLoss(faults.loss())
                .withDuplication(faults.duplication()).withReorder(faults.reorder(), faults.reorder() > 0 ? 30 : 0));
    }

    @Override
    public Peer peer(String vehicleId) {
        var transport = network.attach(Address.loopback(nextPort++));
        var builder = CommunicationManager.builder(vehicleId, transport, scheduler, scheduler)
                .random(seeds.split()).settings(settings);
        return new Peer(builder, scheduler, signal);
    }

    @Override
    public void onCell(Peer peer, Runnable action) {
        action.run();
    }

    @Override
    public void awaitUntil(BooleanSupplier done, long withinMillis) {
        assertTrue(scheduler.runUntil(done, scheduler.nowMillis() + withinMillis),
                "not done within " + withinMillis + " ms of virtual time");
    }

    @Override
    public void makeUnreachable(Peer peer) {
        network.crash(peer.address());
    }

    @Override
    public long slackMillis() {
        return 0;
    }

    @Override
    public void close() {
    }
}
