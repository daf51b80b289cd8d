package net.smc.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import net.smc.core.transport.udp.StatusClient;
import net.smc.core.transport.udp.StatusResponder;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code smc node}: its argument and file checks, and two real nodes on UDP loopback, a commander
 * and a vehicle able to aggregate, which the commander makes its aggregator.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class NodeCommandTest {
    private static final Path PROJECT = Path.of(System.getProperty("smc.project.dir", "..")).toAbsolutePath();
    private static final String MISSION = PROJECT.resolve("missions/reconnaissance.instance.xml").toString();

    @TempDir
    Path dir;

    private Smc smc;
    private final List<RunningNode> nodes = new ArrayList<>();

    @BeforeEach
    void setUp() {
        smc = Smc.in(dir);
        assertEquals(0, smc.run("keys", "authority", "--out", "keys").status());
        for (String id : List.of("cdr", "a1")) {
            assertEquals(0, smc.run("keys", "vehicle", "--id", id, "--out", "keys").status());
            assertEquals(0, smc.run("keys", "issue", "--authority", "keys/authority.key", "--vehicle-pub", "keys/" + id + ".pub",
                    "--id", id, "--mission", "HouseSurvey", "--valid-for", "1h", "--out", "keys/" + id + ".cred").status());
        }
    }

    @AfterEach
    void stopNodes() {
        nodes.forEach(node -> node.stop("the test ended"));
    }

    /** The arguments of vehicle {@code id}'s node, with {@code more} after them. */
    private static List<String> args(String id, String bind, String broadcast, String... more) {
        List<String> args = new ArrayList<>(List.of("node", "--mission", MISSION, "--credential", "keys/" + id + ".cred",
                "--key", "keys/" + id + ".key", "--authority", "keys/authority.pub", "--bind", bind, "--broadcast", broadcast));
        args.addAll(List.of(more));
        return args;
    }

    private Smc.Result node(List<String> args) {
        return smc.run(args.toArray(String[]::new));
    }

    @Test
    void twoNodesOnLoopback_theCommanderMakesTheOtherItsAggregator_andStatusShowsIt() throws Exception {
        String broadcast = "127.255.255.255:" + freePort();
        String cdrAt = "127.0.0.1:" + freePort();
        String a1At = "127.0.0.1:" + freePort();
        RunningNode cdr = start(args("cdr", cdrAt, broadcast, "--commander", "--resources", "communication"));
        RunningNode a1 = start(args("a1", a1At, broadcast, "--resources", "communication", "--tasks", "Aggregator", "--id", "a1"));

        String view = awaitStatus(a1At, json -> json.contains("\"roles\":[\"aggregator#0\"]"));

        assertTrue(view.contains("\"parent\":\"cdr\""), view);
        assertTrue(StatusClient.query(address(cdrAt), Duration.ofSeconds(2)).contains("\"children\":{\"a1\":[\"aggregator#0\"]}"));
        assertEquals(a1At, replySource(a1At), "the status reply leaves from the bound unicast port");
        assertEquals(0, a1.stop("the test is done"));
        assertEquals(0, cdr.stop("the test is done"));
        List<String> lines = a1.out().lines().toList();
        assertEquals("up: vehicle a1 of mission HouseSurvey at " + a1At + ", broadcast " + broadcast
                + ", commander: no, resources [communication], tasks [Aggregator]", lines.get(0));
        assertTrue(lines.stream().anyMatch(l -> l.matches("\\d+ a1 +ACCEPTED +aggregator#0 \\[HouseSurvey\\|1\\|3] from cdr.*")),
                a1.out());
        assertEquals("down: vehicle a1 stopped: the test is done", lines.get(lines.size() - 1));
        List<String> cdrLines = cdr.out().lines().toList();
        assertTrue(cdrLines.get(0).startsWith("up: vehicle cdr of mission HouseSurvey at " + cdrAt), cdr.out());
        assertTrue(cdrLines.get(1).matches("\\d+ cdr +COMMANDING +acting commander of HouseSurvey.*"), cdr.out());
        assertTrue(cdrLines.contains(NodeLog.POLICY_PREFIX + "Received event:newUAV"), cdr.out());
        assertEquals("", a1.err() + cdr.err());
    }

    @Test
    void missingOptions_areAUsageError() {
        Smc.Result result = smc.run("node", "--mission", MISSION);

        assertEquals(2, result.status());
        assertTrue(result.errLines().get(0).startsWith("smc node: Missing required options: '--credential=FILE', "
                + "'--key=FILE', '--authority=FILE', '--bind=ADDR:PORT', '--broadcast=ADDR:PORT'"), result.err());
        assertTrue(result.err().contains("Usage: smc node "), result.err());
    }

    @Test
    void malformedBind_isAUsageErrorSayingWhatIsExpected() {
        Smc.Result result = node(args("a1", "localhost:4000", "127.255.255.255:47474"));

        assertEquals(2, result.status());
        assertEquals("smc node: Invalid value for option '--bind': 'localhost:4000' is not ADDR:PORT; expected an IPv4 "
                + "address and a UDP port 1-65535, e.g. 127.0.0.1:4000", result.errLines().get(0));
    }

    @Test
    void wildcardBind_isAUsageError() {
        Smc.Result result = node(args("a1", "0.0.0.0:4000", "127.255.255.255:47474"));

        assertEquals(2, result.status());
        assertEquals("smc node: --bind 0.0.0.0:4000: 0.0.0.0 cannot be told to other nodes as where to reply; give an "
                + "address of this host, e.g. 10.0.0.7:4000", result.errLines().get(0));
    }

    @Test
    void bindOnTheBroadcastPort_isAUsageError() {
        Smc.Result result = node(args("a1", "127.0.0.1:47474", "127.255.255.255:47474"));

        assertEquals(2, result.status());
        assertEquals("smc node: --bind 127.0.0.1:47474 has the port of --broadcast 127.255.255.255:47474; a node needs a "
                + "unicast port of its own beside the team's shared broadcast port", result.errLines().get(0));
    }

    @Test
    void unknownTask_isAUsageErrorListingTheKnownTasks() {
        Smc.Result result = node(args("a1", "127.0.0.1:4000", "127.255.255.255:47474", "--tasks", "Explorer,Teleporter"));

        assertEquals(2, result.status());
        assertEquals("smc node: --tasks 'Teleporter' is not a known task; the known tasks are Aggregator, Assist, Beacon,"
                + " Explorer, HazardDetector, Navigator, Relay", result.errLines().get(0));
    }

    @Test
    void theAdvertisedDescription_isEachTasksTableVDescription_andSurvivesTheFullCapabilityReply() throws Exception {
        net.smc.core.capability.CapabilityDescription d =
                NodeCommand.describe("a1", List.of("communication"), List.of("Navigator", "Aggregator"));

        assertEquals(List.of("Aggregator", "Navigator"), List.copyOf(d.taskNames()));
        net.smc.core.capability.TaskDescription nav = d.task("Navigator").orElseThrow();
        assertTrue(nav.operations().contains(new net.smc.core.capability.OperationDescription("goTo", List.of("double", "double"))),
                nav.toString());
        assertEquals(List.of("arrived", "blocked"), nav.events().stream().map(e -> e.name()).toList());
        net.smc.core.capability.CapabilityCodec codec = net.smc.core.capability.CapabilityCodec.STANDARD;
        assertEquals(d, codec.decodeDescription(codec.encode(d)));
    }

    @Test
    void badResourceName_isAUsageErrorNamingIt() {
        Smc.Result result = node(args("a1", "127.0.0.1:4000", "127.255.255.255:47474", "--resources", "motion,,video"));

        assertEquals(2, result.status());
        assertEquals("smc node: --resources '' is not a name: it must be 1 to 64 of A-Z a-z 0-9 _ . -, starting with a "
                + "letter (several are separated by commas)", result.errLines().get(0));
    }

    @Test
    void idNotMatchingTheCredential_isAUsageError() {
        Smc.Result result = node(args("a1", "127.0.0.1:4000", "127.255.255.255:47474", "--id", "a2"));

        assertEquals(2, result.status());
        assertEquals("smc node: --id 'a2' does not match --credential keys/a1.cred, which is for vehicle 'a1'",
                result.errLines().get(0));
    }

    @Test
    void aPublicKeyGivenAsTheCredential_isRefusedNamingTheFileAndTheProblem_exitStatus1() {
        List<String> args = args("a1", "127.0.0.1:4000", "127.255.255.255:47474");
        args.set(args.indexOf("keys/a1.cred"), "keys/a1.pub");

        Smc.Result result = node(args);

        assertEquals(1, result.status());
        assertEquals(List.of("smc node: --credential keys/a1.pub: line 1 is 'smc-key v1 ed25519-public' (that is the header "
                + "of an Ed25519 public key file); expected 'smc-credential v1', the header of a credential file"),
                result.errLines());
        assertEquals("", result.out());
    }

    @Test
    void missingKeyFile_isRefusedNamingIt_exitStatus1() {
        List<String> args = args("a1", "127.0.0.1:4000", "127.255.255.255:47474");
        args.set(args.indexOf("keys/a1.key"), "keys/nobody.key");

        Smc.Result result = node(args);

        assertEquals(1, result.status());
        assertEquals(List.of("smc node: --key keys/nobody.key: cannot read it: no such file"), result.errLines());
    }

    @Test
    void credentialOfAnotherAuthority_isRefused_exitStatus1() {
        assertEquals(0, smc.run("keys", "authority", "--out", "other").status());

        Smc.Result result = node(args("a1", "127.0.0.1:4000", "127.255.255.255:47474").stream()
                .map(a -> a.equals("keys/authority.pub") ? "other/authority.pub" : a).toList());

        assertEquals(1, result.status());
        assertTrue(result.errLines().get(0).matches("smc node: --credential keys/a1.cred: issued by authority [0-9a-f]+, "
                + "not by the authority of --authority other/authority.pub \\([0-9a-f]+\\)"), result.err());
    }

    @Test
    void missionWithErrors_listsThem_exitStatus1() throws IOException {
        Path bad = dir.resolve("bad.instance.xml");
        Files.writeString(bad, "<xml><missionInstanceParameters>");
        List<String> args = args("a1", "127.0.0.1:4000", "127.255.255.255:47474", "--repository", PROJECT.resolve("policies").toString());
        args.set(args.indexOf(MISSION), bad.toString());

        Smc.Result result = node(args);

        assertEquals(1, result.status());
        assertTrue(result.errLines().get(0).startsWith(bad + ":1:"), result.err());
        assertTrue(result.err().contains("smc node: --mission " + bad + ": the mission has "), result.err());
    }

    @Test
    void help_explainsTheOutputAndTheExitStatuses() {
        Smc.Result result = smc.run("node", "--help");

        assertEquals(0, result.status());
        assertTrue(result.out().startsWith("Usage: smc node "), result.out());
        assertTrue(result.out().contains("first 'up: vehicle ID"), result.out());
        assertTrue(result.out().contains("2   usage error"), result.out());
        assertTrue(smc.run("--help").out().contains("node"));
    }

    // ---------------------------------------------------------------- running nodes in threads

    /** A node running on a thread of the test JVM, its output captured, stopped by its own signal. */
    private record RunningNode(CompletableFuture<Integer> status, StringWriter stdout, StringWriter stderr, StopSignal signal) {
        int stop(String why) {
            signal.trigger(why);
            return status.orTimeout(10, TimeUnit.SECONDS).join();
        }

        String out() {
            return stdout.toString();
        }

        String err() {
            return stderr.toString();
        }
    }

    /** Starts {@code smc ARGS} on a thread and returns once its first line says it is up. */
    private RunningNode start(List<String> args) throws InterruptedException {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        Io io = new Io(new ByteArrayInputStream(new byte[0]), new PrintWriter(out, true), new PrintWriter(err, true), false, dir);
        StopSignal signal = StopSignal.manual();
        CompletableFuture<Integer> status = CompletableFuture.supplyAsync(
                () -> Main.commandLine(io, () -> signal).execute(args.toArray(String[]::new)), r -> new Thread(r, "node").start());
        RunningNode node = new RunningNode(status, out, err, signal);
        nodes.add(node);
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!out.toString().startsWith("up: ")) {
            assertTrue(System.nanoTime() < deadline && !status.isDone(), () -> "the node did not come up: " + out + err);
            Thread.sleep(10);
        }
        return node;
    }

    /** The first status view of the node at {@code at} that {@code wanted} accepts, asked every 100 ms for 20 s. */
    private static String awaitStatus(String at, java.util.function.Predicate<String> wanted) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        String json = "";
        while (System.nanoTime() < deadline) {
            json = StatusClient.query(address(at), Duration.ofSeconds(1));
            if (wanted.test(json)) {
                return json;
            }
            Thread.sleep(100);
        }
        throw new AssertionError("the node at " + at + " never showed the expected view; last: " + json);
    }

    /** Sends a status query to {@code at} and answers the address the reply came from. */
    private static String replySource(String at) throws IOException {
        try (DatagramSocket socket = new DatagramSocket()) {
            socket.setSoTimeout(2_000);
            byte[] query = StatusResponder.query();
            socket.send(new DatagramPacket(query, query.length, address(at)));
            DatagramPacket reply = new DatagramPacket(new byte[2048], 2048);
            socket.receive(reply);
            assertTrue(StatusResponder.replyJson(reply.getData(), reply.getLength()) != null, "a status reply");
            return reply.getAddress().getHostAddress() + ":" + reply.getPort();
        }
    }

    private static InetSocketAddress address(String at) {
        int colon = at.lastIndexOf(':');
        return new InetSocketAddress(at.substring(0, colon), Integer.parseInt(at.substring(colon + 1)));
    }

    /** A UDP port free on this machine now. */
    private static int freePort() {
        try (DatagramSocket probe = new DatagramSocket(new InetSocketAddress("0.0.0.0", 0))) {
            return probe.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
