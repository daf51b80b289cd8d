package net.smc.sim.team;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import net.smc.core.transport.Address;
import net.smc.core.transport.Transport;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.core.transport.sim.NetworkObserver;
import net.smc.core.transport.sim.SimulationScheduler;

/**
 * An attacker on the radio channel of a simulated team, driven by the simulation's seed. It hears
 * every datagram the network delivers (it keeps the latest {@link #RECORDED}) and, every
 * {@link #PERIOD_MILLIS} of virtual time, does one of:
 * <ul>
 *   <li>replays a recorded datagram, at once or up to 20 s later, to its destination or to another
 *       vehicle, under its true source address;</li>
 *   <li>re-orders: sends a run of recent datagrams again, newest first, with growing delays;</li>
 *   <li>flips one to three bits of a recorded datagram and sends it on;</li>
 *   <li>floods forged datagrams: random bytes, or recorded ones under another vehicle's address.</li>
 * </ul>
 * It cannot stop or delay honest traffic (that is the network's loss and partitions). Everything it
 * sends goes through {@link InMemoryNetwork#inject}, past partitions and loss, and must be refused
 * by the vehicles' authentication; the team's invariants must hold all the same.
 */
public final class Adversary implements NetworkObserver {
    /** How many of the latest delivered datagrams it keeps. */
    static final int RECORDED = 256;
    /** Virtual time between its actions. */
    static final long PERIOD_MILLIS = 100;
    private static final int FLOOD = 8;

    private record Heard(Address from, Address to, byte[] data) {
    }

    private final InMemoryNetwork network;
    private final SimulationScheduler scheduler;
    private final SplittableRandom random;
    private final List<Address> targets;
    private final Heard[] heard = new Heard[RECORDED];
    private int heardCount;
    private long sent;
    private boolean stopped;

    /**
     * @param targets the vehicles' addresses (it sends to these, and forges them as sources)
     */
    Adversary(InMemoryNetwork network, SimulationScheduler scheduler, long seed, List<Address> targets) {
        this.network = network;
        this.scheduler = scheduler;
        this.random = new SplittableRandom(seed ^ 0x9E3779B97F4A7C15L);
        this.targets = new ArrayList<>(targets);
    }

    /** Starts listening and acting. */
    void start() {
        network.addObserver(this);
        scheduler.schedule(PERIOD_MILLIS, this::act);
    }

    /** Stops acting (it goes on hearing, harmlessly). */
    void stop() {
        stopped = true;
    }

    /** A vehicle that joined: a new target. */
    void target(Address address) {
        if (!targets.contains(address)) {
            targets.add(address);
        }
    }

    /** Datagrams it has put on the air. */
    public long sent() {
        return sent;
    }

    @Override
    public void delivered(long atMillis, Address from, Address to, byte[] data) {
        heard[heardCount++ % RECORDED] = new Heard(from, to, data.clone());
    }

    private void act() {
        if (stopped) {
            return;
        }
        scheduler.schedule(PERIOD_MILLIS, this::act);
        if (heardCount == 0 || targets.isEmpty()) {
            return;
        }
        switch (random.nextInt(4)) {
            case 0 -> {
                Heard h = pick();
                Address to = random.nextInt(4) == 0 ? target() : h.to;
                inject(h.from, to, h.data, random.nextInt(4) == 0 ? random.nextLong(20_000) : 0);
            }
            case 1 -> {
                int run = 1 + random.nextInt(Math.min(8, Math.min(heardCount, RECORDED)));
                for (int i = 0; i < run; i++) {
                    Heard h = heard[Math.floorMod(heardCount - 1 - i, RECORDED)];
                    inject(h.from, h.to, h.data, (run - i) * 5L);
                }
            }
            case 2 -> {
                Heard h = pick();
                byte[] flipped = h.data.clone();
                int flips = 1 + random.nextInt(3);
                for (int i = 0; i < flips; i++) {
                    flipped[random.nextInt(flipped.length)] ^= (byte) (1 << random.nextInt(8));
                }
                inject(h.from, h.to, flipped, random.nextInt(50));
            }
            default -> {
                for (int i = 0; i < FLOOD; i++) {
                    Address from = target();
                    byte[] data;
                    if (random.nextBoolean()) {
                        data = new byte[1 + random.nextInt(Transport.MAX_DATAGRAM_BYTES)];
                        random.nextBytes(data);
                    } else {
                        data = pick().data;
                    }
                    inject(from, target(), data, random.nextInt(50));
                }
            }
        }
    }

    private void inject(Address from, Address to, byte[] data, long delayMillis) {
        sent++;
        network.inject(from, to, data, delayMillis);
    }

    private Heard pick() {
        return heard[random.nextInt(Math.min(heardCount, RECORDED))];
    }

    private Address target() {
        return targets.get(random.nextInt(targets.size()));
    }
}
