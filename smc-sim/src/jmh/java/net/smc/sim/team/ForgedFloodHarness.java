package net.smc.sim.team;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentLinkedQueue;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.MissionState;
import net.smc.core.host.CellHost;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.core.security.SecureEndpoint;
import net.smc.core.transport.real.SystemClock;
import net.smc.core.transport.udp.StatusClient;
import net.smc.core.transport.udp.UdpEventLoop;
import net.smc.core.transport.udp.UdpSettings;
import net.smc.policy.api.PolicyRepository;

/**
 * A forged-signature flood against an authenticated team on loopback UDP: the reconnaissance team's
 * minimal configuration (commander, aggregator, two surveyors; a {@link CellHost} each) forms, then
 * one sender floods the shared broadcast port with real signed datagrams (the commander's, made
 * afresh every second) each with one byte of its signature flipped. Meanwhile every member's status
 * is asked every 500 ms. Prints the datagrams sent, the cells' CPU time, the slowest status answer,
 * the failures, suspensions and role losses seen, and whether every member still holds its role.
 *
 * <pre>./gradlew :smc-core:jmh -PjmhMain=net.smc.core.cell.ForgedFloodHarness -PjmhArgs="20000 60"</pre>
 * (arguments: forged datagrams per second (20000), seconds (60), project directory (..))
 */
public final class ForgedFloodHarness {
    public static void main(String[] args) throws Exception {
        int rate = args.length > 0 ? Integer.parseInt(args[0]) : 20_000;
        int seconds = args.length > 1 ? Integer.parseInt(args[1]) : 60;
        Path project = Path.of(args.length > 2 ? args[2] : "..");
        PolicyRepository repository = new PolicyRepository(project.resolve("policies"));
        Mission mission = new MissionLoader(repository).load(project.resolve("missions/reconnaissance.instance.xml"));
        int broadcastPort = freePort();
        ConcurrentLinkedQueue<CellEvent> events = new ConcurrentLinkedQueue<>();
        Map<String, CellHost> hosts = new LinkedHashMap<>();
        Map<String, InetSocketAddress> at = new LinkedHashMap<>();
        List<SimVehicle> team = new ArrayList<>(SimVehicle.reconnaissance(2, 1, 0, 0));
        team.sort((x, y) -> Boolean.compare(x.commander(), y.commander()));   // the commander last
        try (UdpEventLoop loop = UdpEventLoop.create(1)) {
            for (SimVehicle v : team) {
                int port = freePort();
                CellHost.Settings s = CellHost.settings(v.id(), mission, v.description(), repository)
                        .udp(UdpSettings.defaults().withPort(port).withBroadcast("127.255.255.255", broadcastPort))
                        .commander(v.commander()).seed(7 + port).trace(events::add)
                        .security(SimIdentities.identity(v, mission.instanceName()), SimIdentities.trust(mission.instanceName()));
                hosts.put(v.id(), CellHost.open(s, loop));
                at.put(v.id(), new InetSocketAddress("127.0.0.1", port));
            }
            CellHost cdr = hosts.get("cdr");
            long deadline = System.nanoTime() + 30_000_000_000L;
            while (!cdr.call(() -> cdr.cell().missionState()).equals(Optional.of(MissionState.RUNNING))
                    && !cdr.call(() -> cdr.cell().missionState()).equals(Optional.of(MissionState.OPTIMAL))) {
                if (System.nanoTime() > deadline) {
                    throw new IllegalStateException("the team did not form within 30 s");
                }
                Thread.sleep(100);
            }
            Thread.sleep(2_000);
            events.clear();
            Map<String, List<String>> rolesBefore = roles(hosts);
            SimVehicle commander = team.stream().filter(SimVehicle::commander).findFirst().orElseThrow();
            SecureEndpoint forger = SecureEndpoint.builder(SimIdentities.identity(commander, mission.instanceName()),
                    SimIdentities.trust(mission.instanceName()), new SystemClock()).build();
            ThreadMXBean threads = ManagementFactory.getThreadMXBean();
            long cpuBefore = cellCpu(threads);

            Thread flooder = new Thread(() -> flood(forger, broadcastPort, rate, seconds), "flooder");
            flooder.start();
            long slowest = 0;
            int asked = 0;
            int late = 0;
            long end = System.nanoTime() + seconds * 1_000_000_000L;
            while (System.nanoTime() < end) {
                for (Map.Entry<String, InetSocketAddress> e : at.entrySet()) {
                    long t0 = System.nanoTime();
                    asked++;
                    try {
                        StatusClient.query(e.getValue(), Duration.ofSeconds(2));
                    } catch (java.io.IOException x) {
                        late++;
                        continue;
                    }
                    long took = (System.nanoTime() - t0) / 1_000_000;
                    slowest = Math.max(slowest, took);
                    if (took > 1_000) {
                        late++;
                    }
                }
                Thread.sleep(500);
            }
            flooder.join();
            long cpu = cellCpu(threads) - cpuBefore;
            Map<String, List<String>> rolesAfter = roles(hosts);
            long failures = events.stream().filter(e -> e.kind() == CellEvent.Kind.FAILURE).count();
            long released = events.stream().filter(e -> e.kind() == CellEvent.Kind.RELEASED).count();
            long suspensions = events.stream().filter(e -> e.kind() == CellEvent.Kind.SUSPENDED).count();
            boolean suspended = suspensions > 0;
            for (CellHost h : hosts.values()) {
                suspended |= h.call(() -> h.cell().isSuspended());
            }
            System.out.printf(Locale.ROOT, "measured: %d forged datagrams/s for %d s to the broadcast port; cells' threads used %.1f s of CPU (%.1f µs per forged datagram per cell)%n",
                    rate, seconds, cpu / 1e9, cpu / 1e3 / ((double) rate * seconds * hosts.size()));
            System.out.printf(Locale.ROOT, "measured: status: %d asked, %d unanswered or over 1 s, slowest answer %d ms%n", asked, late, slowest);
            System.out.printf(Locale.ROOT, "measured: failures raised %d, roles released %d, any cell suspended %b, roles unchanged %b%n",
                    failures, released, suspended, rolesBefore.equals(rolesAfter));
            System.out.println("roles before " + rolesBefore + "\nroles after  " + rolesAfter);
            for (CellHost h : hosts.values()) {
                h.close();
            }
        }
    }

    private static Map<String, List<String>> roles(Map<String, CellHost> hosts) {
        Map<String, List<String>> roles = new LinkedHashMap<>();
        for (Map.Entry<String, CellHost> e : hosts.entrySet()) {
            CellHost h = e.getValue();
            roles.put(e.getKey(), h.call(() -> h.cell().seats().stream().map(s -> s.role() + "#" + s.slot()).sorted().toList()));
        }
        return roles;
    }

    /** CPU time of the cells' threads (named {@code cell-...}) and the event loop's. */
    private static long cellCpu(ThreadMXBean threads) {
        long sum = 0;
        for (long id : threads.getAllThreadIds()) {
            java.lang.management.ThreadInfo info = threads.getThreadInfo(id);
            if (info != null && !info.getThreadName().equals("flooder") && !info.getThreadName().startsWith("main")) {
                long t = threads.getThreadCpuTime(id);
                if (t > 0 && (info.getThreadName().startsWith("cell-") || info.getThreadName().contains("loop")
                        || info.getThreadName().contains("epoll") || info.getThreadName().contains("nio"))) {
                    sum += t;
                }
            }
        }
        return sum;
    }

    private static void flood(SecureEndpoint forger, int broadcastPort, int rate, int seconds) {
        try (DatagramSocket socket = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            socket.setBroadcast(true);
            InetAddress to = InetAddress.getByName("127.255.255.255");
            long start = System.nanoTime();
            long sent = 0;
            byte[] forged = null;
            long madeAt = -1;
            for (long now = System.nanoTime(); now - start < seconds * 1_000_000_000L; now = System.nanoTime()) {
                long second = (now - start) / 1_000_000_000L;
                if (second != madeAt) {
                    forged = forger.wrapSigned("DISCOVERY?".getBytes(StandardCharsets.UTF_8));
                    madeAt = second;
                }
                long due = (now - start) * rate / 1_000_000_000L;
                for (; sent < due; sent++) {
                    forged[forged.length - 1 - (int) (sent % 60)] ^= 0x01;   // a different flip each time
                    socket.send(new DatagramPacket(forged, forged.length, to, broadcastPort));
                    forged[forged.length - 1 - (int) (sent % 60)] ^= 0x01;
                }
                java.util.concurrent.locks.LockSupport.parkNanos(500_000);   // batches every half millisecond: no busy core
            }
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static int freePort() throws java.io.IOException {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress("0.0.0.0", 0))) {
            return probe.getLocalPort();
        }
    }
}
