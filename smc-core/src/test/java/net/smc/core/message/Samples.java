package net.smc.core.message;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.capability.EventDescription;
import net.smc.core.capability.OperationDescription;
import net.smc.core.capability.TaskDescription;

/** Valid messages of every type, ordinary and at their limits, shared by the codec tests. */
final class Samples {
    /**
     * One manager's role-mission as the set-up time experiment generates them (796 bytes): for the
     * policy-text coding's tests and benchmark.
     */
    static final String MANAGER_ROLE_MISSION = """
            // Role-mission of b0l1 (generated): it finds a vehicle for each role it manages
            // (newUAV: the vehicle has the role's kit; then its full capability description is asked for)
            // and has a failed holder's role re-assigned.

            assign := root/factory/ecapolicy create.
            assign event: /event/newUAV;
                condition: [:lowLevelCap :uav :credential |
                    root/discovery uav: uav has: #("kit_b0l2") cap: lowLevelCap auth: credential];
                action: [:uav | root/discovery fullCapReq: uav role: "b0l2"].
            root/role/b0l1/policy at: "assign_b0l2" put: assign.

            reassign := root/factory/ecapolicy create.
            reassign event: /event/UAVFailure;
                condition: [:role | role == "b0l2"];
                action: [:role | root/role/b0l1 reassign: role scheme: "default"].
            root/role/b0l1/policy at: "reassign_b0l2" put: reassign.
            """;

    private Samples() {
    }

    static final Identity IDENTITY = new Identity("rescue", 1, 4);

    static CapabilitySummary summary() {
        return new CapabilitySummary("uav2", new java.util.TreeSet<>(Set.of("motion", "video", "infrared")),
                new java.util.TreeSet<>(Set.of("Explorer", "Relay")));
    }

    /** A description with {@code tasks} tasks of {@code ops} operations and {@code ops} events each. */
    static CapabilityDescription description(int tasks, int ops) {
        List<TaskDescription> list = new ArrayList<>();
        for (int t = 0; t < tasks; t++) {
            List<OperationDescription> operations = new ArrayList<>();
            List<EventDescription> events = new ArrayList<>();
            for (int o = 0; o < ops; o++) {
                operations.add(new OperationDescription("moveTo" + o, List.of("double", "double", "String")));
                events.add(new EventDescription("reached" + o, List.of(new EventDescription.Attribute("x", "double"),
                        new EventDescription.Attribute("y", "double"))));
            }
            list.add(new TaskDescription("Task" + t, operations, events));
        }
        list.add(TaskDescription.empty("Idle"));
        return CapabilityDescription.of("uav2", Set.of("motion", "video", "communication"), list);
    }

    /** ASCII text of exactly {@code bytes} bytes. */
    static String ascii(int bytes) {
        char[] c = new char[bytes];
        for (int i = 0; i < bytes; i++) {
            c[i] = (char) ('a' + i % 26);
        }
        return new String(c);
    }

    /** Text of exactly {@code bytes} UTF-8 bytes mixing 1-, 2-, 3- and 4-byte characters. */
    static String mixed(int bytes) {
        StringBuilder sb = new StringBuilder();
        String[] pieces = {"a", "é", "€", "\uD83D\uDE81"};  // 1, 2, 3, 4 bytes (the last: a helicopter)
        int n = 0;
        for (int i = 0; n < bytes; i++) {
            String p = pieces[i % 4];
            int len = Utf8.length(p);
            if (n + len > bytes) {
                p = "z";
                len = 1;
            }
            sb.append(p);
            n += len;
        }
        return sb.toString();
    }

    /** A policy text of {@code bytes} bytes that looks like PonderTalk. */
    static String policyText(int bytes) {
        String line = "p := root/factory/ecapolicy create. p event: /event/newUAV; active: true.\n";
        StringBuilder sb = new StringBuilder();
        while (sb.length() + line.length() <= bytes) {
            sb.append(line);
        }
        sb.append(ascii(bytes - sb.length()));
        return sb.toString();
    }

    /**
     * A role event carrying {@code bytes} bytes of ASCII text in strings of at most 4,000 bytes: a
     * large message whose payload the codec writes as it is (policy texts it compresses). Its
     * payload is {@code 6 + 3k + bytes} bytes for {@code k} strings (role and event "r"/"e", no origin).
     */
    static RoleEvent bulk(String role, int bytes) {
        List<Object> values = new java.util.ArrayList<>();
        for (int left = bytes; left > 0; left -= 4_000) {
            values.add(ascii(Math.min(left, 4_000)));
        }
        return new RoleEvent(role, "e", values);
    }

    /** A list nested {@code depth} deep: {@code [[[x]]]} for 3. */
    static List<Object> nested(int depth, Object leaf) {
        List<Object> v = Arrays.asList(leaf);
        for (int i = 1; i < depth; i++) {
            v = Arrays.asList(v, null);
        }
        return v;
    }

    /** The largest number a value may carry: 64 bytes of two's complement. */
    static BigDecimal largestNumber() {
        return new BigDecimal(BigInteger.TWO.pow(511).subtract(BigInteger.ONE), -7);
    }

    /** Messages of every type, small and ordinary. */
    static List<Message> ordinary() {
        List<Object> values = Arrays.asList("found", new BigDecimal("12.50"), Boolean.TRUE, null,
                List.of(new BigDecimal("-3"), "x"));
        return List.of(
                new Discovery("rescue", "commander", 0, 1),
                new DiscoveryReply(11, "rescue", summary()),
                new DiscoveryReply(11, "rescue", "hdetector", summary()),
                new CapabilityRequest("relay"),
                new CapabilityReply(12, description(2, 2)),
                new RoleAssignment("rescue", "relay", IDENTITY, "uav1",
                        List.of(new PolicyRef("policy:/roles/relay", 3), new PolicyRef("policy:/roles/common", 1))),
                new AssignmentResponse(13, "relay", true, ""),
                new AssignmentResponse(14, "medic", false, "no video resource"),
                new PolicyRequest("policy:/roles/relay", 3),
                new PolicyReply(15, "policy:/roles/relay", 3, "p := root/factory/ecapolicy create."),
                new Heartbeat("relay", 42, 1),
                new Heartbeat("relay", 300, 2, 17),
                new Echo(123_456_789L),
                new Echo(0),
                new Ack(Long.MIN_VALUE),
                new RoleEvent("explorer", "soldierFound", values),
                new RoleEvent("hdetector", "hazardDetected", values, "d1"),
                new Invocation("medic", "moveTo:y:", List.of(new BigDecimal("10.5"), new BigDecimal("-2"))),
                new Invocation("aggregator", "report:x:y:", List.of("gas", BigDecimal.ONE, BigDecimal.TEN), "hdetector",
                        Long.MAX_VALUE, "d1", "10.0.0.7:4001"),
                new SubtreeReport("surveyor", List.of("hdetector", BigDecimal.ONE, "#seats", List.of("surveyor#0"))),
                new CellRequest(CellRequest.Kind.EVENT, "a1", "role/aggregator", "", "ping",
                        List.of(List.of("#map", "level", BigDecimal.TEN)), "hdetector", 5, "d1", "10.0.0.7:4001"),
                new CellRequest(CellRequest.Kind.EVALUATE, "a1", "", "execute:", "", List.of("6 * 7."), "hdetector", 6, "", ""),
                InvocationResult.ok(16, List.of("done", Boolean.FALSE)),
                InvocationResult.ok(17, null),
                InvocationResult.failed(18, "no such operation"),
                new Leave("shutting down"),
                new Withdrawal(19, "rescue"),
                new Status("rescue", IDENTITY, "uav1", 7, 5),
                new Status("rescue", IDENTITY, "uav1", 7, 5, 123_456_789L, List.of("uav0")),
                new Status("rescue", IDENTITY, "uav1", 7, 5, 123_456_789L, List.of("uav0"), 200),
                new Acks(List.of(3L, Long.MIN_VALUE, 3L)),
                new RoleAssignment("rescue", "surveyor", IDENTITY, "uav1", List.of(new PolicyRef("policy:/roles/s", 9)),
                        4, List.of(new BigDecimal("3.5"), new BigDecimal("-7")), List.of("hdetector#0", "relay#1"), List.of("uav0", "uav9")),
                new Roster("rescue", 2, List.of("uav2", "uav3"), List.of(new Roster.Entry("uav2", "10.0.0.2:4000",
                        "surveyor", 0), new Roster.Entry("uav3", "10.0.0.3:4000", "aggregator", 0))),
                new Roster("rescue", 0, List.of(), List.of()));
    }

    /** Messages at the limits of their fields (each still fits one datagram with a short sender). */
    static List<Message> boundaries() {
        String name64 = ascii(64);
        String nameMixed = mixed(64);
        List<Object> sixtyFour = new ArrayList<>();
        for (int i = 0; i < 64; i++) {
            sixtyFour.add(i % 2 == 0 ? null : new BigDecimal(i));
        }
        return List.of(
                new Discovery(name64, nameMixed, Integer.MAX_VALUE, Long.MAX_VALUE),
                new Discovery("m", "r", 0, 0),
                new CapabilityRequest(nameMixed),
                new RoleAssignment(nameMixed, name64, new Identity(nameMixed, Integer.MAX_VALUE, Integer.MAX_VALUE),
                        ascii(64), List.of()),
                new AssignmentResponse(Long.MAX_VALUE, "r", false, mixed(255)),
                new PolicyRequest(ascii(255), Integer.MAX_VALUE),
                new PolicyReply(-1, "u", 0, ""),
                new Heartbeat(name64, 0, Integer.MAX_VALUE),
                new Heartbeat("r", Long.MAX_VALUE, 0),
                new Heartbeat("r", 0, 0, Long.MAX_VALUE),
                new Heartbeat("r", 127, 128, 16_383),
                new Echo(Echo.MAX_TAG),
                new Withdrawal(Long.MIN_VALUE, mixed(64)),
                new Ack(Long.MAX_VALUE),
                new RoleEvent("r", "e", List.of()),
                new RoleEvent("r", "e", sixtyFour),
                new RoleEvent("r", "e", List.of(nested(4, "deep"), "", mixed(300))),
                new Invocation("r", "o", List.of(largestNumber(), largestNumber().negate(), BigDecimal.ZERO,
                        new BigDecimal("1E+2147483647"), new BigDecimal("1E-2147483647"))),
                InvocationResult.ok(0, mixed(1000)),
                InvocationResult.failed(0, ascii(255)),
                new Leave(""),
                new Leave(mixed(255)),
                new Status(name64, new Identity(name64, 0, 0), ascii(64), Long.MAX_VALUE, Integer.MAX_VALUE),
                new Status("m", new Identity("m", 0, 0), "c", 0, 0, Long.MAX_VALUE, List.of(), Long.MAX_VALUE),
                new Acks(List.of(Long.MAX_VALUE)),
                new Acks(maxAcks()));
    }

    /** An Acks of the most ids it may hold. */
    static List<Long> maxAcks() {
        List<Long> ids = new ArrayList<>();
        for (long i = 0; i < WireFormat.MAX_ACKS; i++) {
            ids.add(Long.MAX_VALUE - i);
        }
        return ids;
    }

    /** Senders at the limits: the shortest, and 64 bytes in 1-, 2- and 4-byte characters. */
    static List<String> senders() {
        return List.of("u", ascii(64), "é".repeat(32), "\uD83D\uDE81".repeat(16));
    }
}
