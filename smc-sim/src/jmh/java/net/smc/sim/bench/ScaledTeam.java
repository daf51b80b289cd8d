package net.smc.sim.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Scheme;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.core.security.IdealAuthentication;
import net.smc.core.security.WireSizes;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.NetworkObserver;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.experiment.GeneratedMission;
import net.smc.sim.experiment.MissionGenerator;
import net.smc.sim.experiment.TreeShape;
import net.smc.sim.team.TeamSimulation;

/**
 * A team of {@code size} vehicles for the scalability benchmarks: the mission of
 * {@link MissionGenerator} with {@code size} roles (the commander's included) in a management tree
 * of depth {@value #DEPTH} (fan-out the smallest that holds them: 2 for 10 vehicles, 4 for 100, 10
 * for 1,000, 22 for 10,000), distributed scheme, and one vehicle per role, each able to hold only
 * its own. So <i>team size</i> is the number of vehicles, which is the number of roles: every
 * vehicle has a seat and a parent, and formation needs every one of them. The team runs on
 * {@link TeamSimulation}'s simulated network (5 ms latency plus up to 10 ms jitter, no loss, ideal
 * authentication), with its invariants checked every 50 ms of simulated time unless asked not to.
 * The traffic is counted by watching the network, which schedules nothing for it: the team runs
 * as {@link TeamSimulation} runs it in the tests, one scheduled arrival per datagram copy. (A
 * {@link net.smc.core.transport.sim.CpuModel} that only counted, as these benchmarks once
 * installed, makes the network queue each copy at its receiver's CPU: three scheduled steps instead
 * of one, and events in another order.)
 *
 * <p><b>Formed</b> means every seat but the commander's has been accepted (each vehicle loaded and
 * started its role, as the set-up time experiment counts it). Every datagram sent (a broadcast
 * once) is counted with its bytes.
 */
final class ScaledTeam {
    /** Levels of the management tree, the commander's included. */
    static final int DEPTH = 4;
    /** The longest formation waited for, in simulated ms. */
    static final long FORMATION_LIMIT_MILLIS = 600_000;

    /** The generated missions, by size and {@code comTimeout}. */
    private static final Map<List<Long>, Loaded> MISSIONS = new ConcurrentHashMap<>();

    final int size;
    final TeamSimulation sim;
    private final Set<String> accepted = new HashSet<>();
    private long startMillis = -1;
    private long formedMillis = -1;
    private long datagrams;
    private long bytes;
    private final long[] datagramsByType = new long[256];
    private final long[] bytesByType = new long[256];
    private final long[] wireBytesByType = new long[256];
    /** The mission the vehicles' credentials name: its length is in every signed datagram. */
    private final String missionName;
    private long wireBytes;

    private record Loaded(GeneratedMission generated, Mission mission) {
    }

    /** A team with its invariants checked every 50 ms of simulated time. */
    ScaledTeam(int size, long seed) {
        this(size, seed, true);
    }

    /** @param invariants whether the harness checks the team's invariants every 50 ms (off: the cells' own cost) */
    ScaledTeam(int size, long seed, boolean invariants) {
        this(size, seed, invariants, MissionGenerator.COM_TIMEOUT_MILLIS);
    }

    /**
     * @param invariants       whether the harness checks the team's invariants every 50 ms
     * @param comTimeoutMillis the mission's {@code comTimeout}, its heartbeat period ({@code failureTimeout} six of it)
     */
    ScaledTeam(int size, long seed, boolean invariants, long comTimeoutMillis) {
        this.size = size;
        Loaded m = MISSIONS.computeIfAbsent(List.of((long) size, comTimeoutMillis), k -> load(size, comTimeoutMillis));
        this.missionName = m.mission.instanceName();
        Consumer<CellEvent> progress = this::seen;
        this.sim = TeamSimulation.builder(m.mission, new PolicyRepository(m.generated.repository()), seed)
                .vehicles(m.generated.vehicles()).listener(progress).invariantChecks(invariants).build();
        sim.network().addObserver(new Counting());
    }

    /** Starts every cell and runs until the team formed; returns whether it did within the limit. */
    boolean form() {
        sim.start();
        return sim.runUntil(this::formed, FORMATION_LIMIT_MILLIS);
    }

    /**
     * As {@link #form()}, telling {@code progress} after every {@code everyMillis} of simulated time
     * how many seats are accepted.
     */
    boolean form(long everyMillis, java.util.function.IntConsumer progress) {
        sim.start();
        while (!formed() && sim.nowMillis() < FORMATION_LIMIT_MILLIS) {
            sim.runUntil(this::formed, everyMillis);
            progress.accept(accepted.size());
        }
        return formed();
    }

    boolean formed() {
        return accepted.size() >= size - 1;
    }

    /** Simulated ms from the commander's start to the last seat accepted, or -1 before formation. */
    long formationMillis() {
        return formed() && startMillis >= 0 ? formedMillis - startMillis : -1;
    }

    int acceptedSeats() {
        return accepted.size();
    }

    /** Datagrams sent so far by every vehicle (a broadcast counted once). */
    long datagrams() {
        return datagrams;
    }

    /** Bytes of those datagrams. */
    long bytes() {
        return bytes;
    }

    /**
     * Bytes of those datagrams as a real radio carries them once the team has its sessions: each in
     * the envelope the security layer gives it ({@link WireSizes}: {@code PAIR_MAC} for a unicast,
     * {@code SIGNED} with the sender's credential for a broadcast), without the simulation's own
     * seal. The handshakes of first contacts are not counted: for the steady state, where a vehicle
     * has its sessions; during formation this counts low.
     */
    long wireBytes() {
        return wireBytes;
    }

    /** Datagrams sent so far of the frame type {@code code} ({@code MessageType} code, 0xFF a fragment). */
    long datagrams(int code) {
        return datagramsByType[code];
    }

    /** Bytes of those. */
    long bytes(int code) {
        return bytesByType[code];
    }

    /** Bytes of those in the real security envelopes ({@link #wireBytes}). */
    long wireBytes(int code) {
        return wireBytesByType[code];
    }

    private void seen(CellEvent e) {
        if (e.kind() == CellEvent.Kind.COMMANDING && e.vehicle().equals(GeneratedMission.COMMANDER) && startMillis < 0) {
            startMillis = e.timeMillis();
        } else if (e.kind() == CellEvent.Kind.ACCEPTED) {
            int space = e.detail().indexOf(' ');
            if (accepted.add(space < 0 ? e.detail() : e.detail().substring(0, space)) && formed()) {
                formedMillis = e.timeMillis();
            }
        }
    }

    /** Counts what is sent, as the network sees it leave. */
    private final class Counting implements NetworkObserver {
        /**
         * Per sending address, the bytes the real security envelopes add round a payload:
         * {@code PAIR_MAC} then {@code SIGNED}; found once per address, from the vehicle there (most
         * headers leave the sender to the transport).
         */
        private final Map<Address, int[]> envelopes = new HashMap<>();

        @Override
        public void sent(long atMillis, Address from, Address to, byte[] data) {
            datagrams++;
            bytes += data.length;
            long wire = wireLength(from, to, data);
            wireBytes += wire;
            int type = typeOf(data);
            datagramsByType[type]++;
            bytesByType[type] += data.length;
            wireBytesByType[type] += wire;
        }

        /** {@code data}'s length in the envelope a real security layer gives it ({@link #wireBytes}). */
        private long wireLength(Address from, Address to, byte[] data) {
            boolean sealed = data.length >= IdealAuthentication.SEAL_BYTES + 5
                    && data[IdealAuthentication.PAYLOAD_OFFSET] == 'S' && data[IdealAuthentication.PAYLOAD_OFFSET + 1] == 'M';
            int payload = sealed ? data.length - IdealAuthentication.SEAL_BYTES : data.length;
            int[] envelope = envelopes.computeIfAbsent(from, a -> {
                String sender = sim.vehicleAt(a).orElseThrow(() -> new IllegalStateException("no vehicle at " + a));
                return new int[] {WireSizes.pairMac(sender, 0), WireSizes.signed(sender, missionName, 0)};
            });
            return payload + envelope[to == null ? 1 : 0];
        }

        /**
         * The frame's type byte (wire-format.md: after the magic "SM" and the version), found in a
         * datagram sealed by the ideal authentication (an 8-byte counter first) or not; 0 if neither.
         */
        private int typeOf(byte[] data) {
            for (int at : new int[] {0, 8}) {
                if (data.length > at + 3 && data[at] == 'S' && data[at + 1] == 'M') {
                    return data[at + 3] & 0xFF;
                }
            }
            return 0;
        }
    }

    private static Loaded load(int size, long comTimeoutMillis) {
        try {
            Path project = projectDirectory();
            Path dir = Files.createTempDirectory("smc-scale-" + size + "-");
            GeneratedMission g = MissionGenerator.write(TreeShape.of(size, DEPTH), dir,
                    project.resolve("policies/boot/events.p2"), comTimeoutMillis);
            Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.DISTRIBUTED));
            return new Loaded(g, mission);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (Exception e) {
            throw new IllegalStateException("cannot generate the mission of " + size + " roles: " + e.getMessage(), e);
        }
    }

    /** The project's root: the working directory or its parent (Gradle runs JMH in the module's folder). */
    static Path projectDirectory() {
        for (Path p : new Path[] {Path.of(""), Path.of("..")}) {
            if (Files.isRegularFile(p.resolve("policies/boot/events.p2"))) {
                return p;
            }
        }
        throw new IllegalStateException("policies/boot/events.p2 not found in " + Path.of("").toAbsolutePath()
                + " or its parent; run from the project or a module folder");
    }
}
