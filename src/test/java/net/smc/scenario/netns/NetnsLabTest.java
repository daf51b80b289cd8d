package net.smc.scenario.netns;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The network namespace lab: hosts reach each other by unicast and subnet broadcast, a cut host
 * hears and reaches no one until healed, a lossy host loses about its share, and closing leaves
 * nothing behind. Skipped, with the reason, where namespaces cannot be made (not root, no iproute2).
 * Traffic comes from {@link UdpProbe} processes started in the hosts' namespaces.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class NetnsLabTest {
    private static final Duration WAIT = Duration.ofSeconds(15);
    private static final Pattern ROUND = Pattern.compile("end \\d+: (\\d+) data");

    /** Three hosts shared by the tests that only send traffic; made at first use, closed after the last test. */
    private static NetnsLab shared;

    @TempDir
    Path dir;

    private final List<Process> started = new ArrayList<>();
    private int sends;

    @AfterEach
    void killStarted() {
        started.forEach(Process::destroyForcibly);
    }

    @AfterAll
    static void closeShared() {
        if (shared != null) {
            shared.close();
        }
    }

    private static void assumeLabAvailable() {
        Optional<String> reason = NetnsLab.unavailableReason();
        assumeTrue(reason.isEmpty(), () -> "no network namespace lab here: " + reason.orElseThrow());
    }

    private static NetnsLab lab() throws IOException {
        assumeLabAvailable();
        if (shared == null) {
            shared = NetnsLab.create("smclabtest", 3);
        }
        return shared;
    }

    /** Starts a listener on {@code host} and returns its log once it is bound. */
    private Path listen(int host, int port) throws Exception {
        Path log = dir.resolve("listen-h" + host + "-" + port + ".log");
        started.add(lab().start(host, UdpProbe.command("listen", "" + port, "30"), log));
        LogWatch.await(log, "the listener on host " + host, line -> line.equals("listening on " + port), WAIT);
        return log;
    }

    /** Sends {@code text} {@code count} times from {@code host} to {@code to}:{@code port}; returns the sender's exit status. */
    private int send(int host, String to, int port, String text, int count) throws Exception {
        Path log = dir.resolve("send-" + (++sends) + ".log");
        Process sender = lab().start(host, UdpProbe.command("send", to, "" + port, text, "" + count), log);
        started.add(sender);
        assertTrue(sender.waitFor(WAIT.toMillis(), TimeUnit.MILLISECONDS), "sender on host " + host + " did not end");
        return sender.exitValue();
    }

    private static String fromHost(int host, String text) throws IOException {
        return "from " + lab().host(host).address() + ":\\d+ " + Pattern.quote(text);
    }

    private static boolean has(Path log, String regex) throws IOException {
        return LogWatch.lines(log).stream().anyMatch(line -> line.matches(regex));
    }

    private static String await(Path log, String regex) throws Exception {
        return LogWatch.await(log, "a line matching '" + regex + "'", line -> line.matches(regex), WAIT);
    }

    @Test
    void hosts_haveTheirOwnNamespaceAndAddress_onOneSubnet() throws Exception {
        NetnsLab lab = lab();
        Path log = dir.resolve("addr.log");

        Process ip = lab.start(2, List.of(Exec.find("ip").orElseThrow().toString(), "-4", "-o", "addr", "show", "dev", "eth0"), log);

        assertTrue(ip.waitFor(WAIT.toMillis(), TimeUnit.MILLISECONDS));
        assertEquals(new NetnsLab.Host(2, lab.run() + "-h2", "10.77.0.12"), lab.host(2));
        assertTrue(LogWatch.lines(log).get(0).contains("inet 10.77.0.12/24 brd 10.77.0.255 "), LogWatch.lines(log).toString());
        assertEquals("10.77.0.255", lab.broadcastAddress());
        assertEquals(3, lab.hosts());
        assertTrue(lab.run().matches("smclabtest-" + ProcessHandle.current().pid() + "-[0-9a-f]{4}"), lab.run());
        assertTrue(Namespaces.names(Exec.find("ip").orElseThrow()).containsAll(
                List.of(lab.bridgeNamespace(), lab.host(0).namespace(), lab.host(1).namespace(), lab.host(2).namespace())));
    }

    @Test
    void unicast_reachesItsHost_andSubnetBroadcast_reachesEveryOtherHost() throws Exception {
        NetnsLab lab = lab();
        Path at1 = listen(1, 5001);
        Path at2 = listen(2, 5001);

        assertEquals(0, send(0, lab.host(1).address(), 5001, "unicast", 1));
        assertEquals(0, send(0, lab.broadcastAddress(), 5001, "broadcast", 1));

        await(at1, fromHost(0, "broadcast"));
        await(at2, fromHost(0, "broadcast"));
        assertTrue(has(at1, fromHost(0, "unicast")), LogWatch.lines(at1).toString());
        assertFalse(has(at2, fromHost(0, "unicast")), "the unicast went to host 1 only: " + LogWatch.lines(at2));
    }

    @Test
    void cut_stopsTrafficBothWays_andHeal_restoresIt() throws Exception {
        NetnsLab lab = lab();
        Path at0 = listen(0, 5002);
        Path at1 = listen(1, 5002);
        send(0, lab.host(1).address(), 5002, "before", 1);
        await(at1, fromHost(0, "before"));   // host 0 now knows host 1's MAC: nothing waits for ARP below

        lab.cut(1);
        try {
            send(0, lab.host(1).address(), 5002, "to the cut host", 3);
            send(1, lab.broadcastAddress(), 5002, "from the cut host", 3);   // its send may fail or vanish
        } finally {
            lab.heal(1);
        }
        assertEquals(0, send(0, lab.host(1).address(), 5002, "after heal", 1));
        assertEquals(0, send(1, lab.broadcastAddress(), 5002, "healed broadcast", 1));

        await(at1, fromHost(0, "after heal"));
        await(at0, fromHost(1, "healed broadcast"));
        assertFalse(has(at1, fromHost(0, "to the cut host")), LogWatch.lines(at1).toString());
        assertFalse(has(at0, fromHost(1, "from the cut host")), LogWatch.lines(at0).toString());
    }

    @ParameterizedTest
    @EnumSource(LossTool.class)
    void loss_dropsAboutItsShare_andClearLoss_dropsNothing(LossTool tool) throws Exception {
        NetnsLab lab = lab();
        if (tool == LossTool.NFT) {
            NetnsLab.ensureLossTool();
        }
        Optional<String> missing = tool.unavailableReason();
        assumeTrue(missing.isEmpty(), () -> "cannot test loss with " + tool + ": " + missing.orElseThrow());
        int port = 5010 + tool.ordinal();
        Path at1 = listen(1, port);
        String to = lab.host(1).address();

        // What the loss tool let through is what the listener read plus what its host's kernel
        // dropped because the listener's socket buffer was full (a listener starved of CPU on a
        // loaded machine): only the tool's share is the test's business.
        lab.loss(1, 20, tool);
        try {
            long overflowBefore = receiveBufferErrors(1);
            send(0, to, port, "data", 1_000);
            send(0, to, port, "end 1", 20);   // 20 markers: at 20% loss, one gets through
            int read = received(await(at1, "end 1: \\d+ data"));
            long overflowed = receiveBufferErrors(1) - overflowBefore;
            long passed = read + overflowed;
            assertTrue(passed >= 720 && passed <= 880, "1,000 sent at 20% loss; " + passed + " passed the tool ("
                    + read + " read, " + overflowed + " dropped by a full socket buffer), expected about 800");
        } finally {
            lab.clearLoss(1);
        }
        long overflowBefore = receiveBufferErrors(1);
        send(0, to, port, "data", 300);
        send(0, to, port, "end 2", 1);
        int read = received(await(at1, "end 2: \\d+ data"));
        assertEquals(300, read + (receiveBufferErrors(1) - overflowBefore), "no loss after clearLoss (" + read + " read)");
    }

    /**
     * The UDP datagrams the kernel of {@code host}'s namespace has dropped so far because a socket's
     * receive buffer was full ({@code RcvbufErrors} of {@code /proc/net/snmp}, counted per namespace).
     */
    private long receiveBufferErrors(int host) throws Exception {
        Path log = dir.resolve("snmp-" + (++sends) + ".log");
        Process cat = lab().start(host, List.of(Exec.find("cat").orElseThrow().toString(), "/proc/net/snmp"), log);
        started.add(cat);
        assertTrue(cat.waitFor(WAIT.toMillis(), TimeUnit.MILLISECONDS), "cat /proc/net/snmp on host " + host + " did not end");
        List<String> udp = LogWatch.lines(log).stream().filter(line -> line.startsWith("Udp: ")).toList();
        assertEquals(2, udp.size(), "the Udp: header and values of /proc/net/snmp on host " + host + ": " + LogWatch.lines(log));
        List<String> names = List.of(udp.get(0).trim().split("\\s+"));
        String[] values = udp.get(1).trim().split("\\s+");
        int at = names.indexOf("RcvbufErrors");
        assertTrue(at > 0, "no RcvbufErrors in /proc/net/snmp on host " + host + ": " + names);
        return Long.parseLong(values[at]);
    }

    private static int received(String roundLine) {
        Matcher m = ROUND.matcher(roundLine);
        assertTrue(m.matches(), roundLine);
        return Integer.parseInt(m.group(1));
    }

    @Test
    void loss_outOfRange_isRefused() throws Exception {
        NetnsLab lab = lab();

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> lab.loss(0, 101, LossTool.NFT));
        assertEquals("a loss of 101% on host 0 cannot be set; it must be 0 to 100", e.getMessage());
    }

    @Test
    void unknownHost_isRefusedNamingTheRange() throws Exception {
        NetnsLab lab = lab();

        IndexOutOfBoundsException e = assertThrows(IndexOutOfBoundsException.class, () -> lab.cut(3));
        assertEquals("host 3 is not in lab " + lab.run() + "; its hosts are 0 to 2", e.getMessage());
    }

    @Test
    void close_killsEveryProcess_evenOnesThatLeftTheirParent_andRemovesEveryNamespace() throws Exception {
        assumeLabAvailable();
        Path ip = Exec.find("ip").orElseThrow();
        NetnsLab lab = NetnsLab.create("smclabclose", 2);
        Process sleeper = lab.start(0, List.of("sleep", "600"), dir.resolve("sleep.log"));
        Path childLog = dir.resolve("child.log");
        lab.start(1, List.of("bash", "-c", "sleep 600 & echo $!; wait"), childLog);
        Path orphanLog = dir.resolve("orphan.log");
        Process parent = lab.start(1, List.of("bash", "-c", "setsid sleep 600 </dev/null >/dev/null 2>&1 & echo $!"), orphanLog);
        long child = Long.parseLong(LogWatch.await(childLog, "the child's pid", line -> line.matches("\\d+"), WAIT));
        long orphan = Long.parseLong(LogWatch.await(orphanLog, "the orphan's pid", line -> line.matches("\\d+"), WAIT));
        assertTrue(parent.waitFor(WAIT.toMillis(), TimeUnit.MILLISECONDS), "the orphan's parent ended");
        assertTrue(ProcessHandle.of(orphan).isPresent(), "the orphan runs on without its parent");

        lab.close();

        assertFalse(sleeper.isAlive());
        assertTrue(ProcessHandle.of(child).isEmpty(), "the child of a started process is killed");
        assertTrue(ProcessHandle.of(orphan).isEmpty(), "a process left in a namespace is killed");
        assertEquals(List.of(), Namespaces.names(ip).stream().filter(n -> n.startsWith(lab.run())).toList());
        lab.close();   // again: nothing to do
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> lab.cut(0));
        assertEquals("network lab " + lab.run() + " is closed", e.getMessage());
    }

    @Test
    void cleanupStale_removesLeftoversOfDeadRuns_andKeepsLiveOnes() throws Exception {
        assumeLabAvailable();
        Path ip = Exec.find("ip").orElseThrow();
        String dead = "smclabstale-4000000000-beef-h0";   // above any pid_max: that run is surely gone
        String live = "smclabstale-" + ProcessHandle.current().pid() + "-beef-h0";
        try {
            Exec.check(List.of(ip.toString(), "netns", "add", dead));
            Exec.check(List.of(ip.toString(), "netns", "add", live));
            Process leftover = new ProcessBuilder(ip.toString(), "netns", "exec", dead, "sleep", "600").start();
            started.add(leftover);

            assertEquals(1, NetnsLab.cleanupStale("smclabstale"));

            List<String> names = Namespaces.names(ip);
            assertFalse(names.contains(dead), names.toString());
            assertTrue(names.contains(live), names.toString());
            assertTrue(leftover.waitFor(WAIT.toMillis(), TimeUnit.MILLISECONDS), "the process in the stale namespace was killed");
        } finally {
            Exec.run(List.of(ip.toString(), "netns", "delete", dead));
            Exec.run(List.of(ip.toString(), "netns", "delete", live));
        }
    }

    @Test
    void create_refusesABadPrefix() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> NetnsLab.create("Lab-1", 2));
        assertEquals("lab prefix 'Lab-1' is not allowed; it must be 1 to 16 lower case letters and digits, starting "
                + "with a letter, e.g. smcnode", e.getMessage());
    }

    @Test
    void create_refusesAHostCountOutsideTheSubnet() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> NetnsLab.create("smclab", 241));
        assertEquals("a lab of 241 hosts cannot be made; it must have 1 to 240 (one address each in 10.77.0.0/24)",
                e.getMessage());
    }
}
