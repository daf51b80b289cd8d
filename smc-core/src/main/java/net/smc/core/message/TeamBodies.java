package net.smc.core.message;

import java.util.ArrayList;
import java.util.List;
import net.smc.core.wire.ByteWriter;

/**
 * Payloads of the team-formation messages: discovery, capabilities, role assignment, status and
 * leave. Fields follow each other in record order; an identity is written as its level and
 * sequence only, since its mission is the message's own.
 */
final class TeamBodies {
    private TeamBodies() {
    }

    static final BodyCodec<Discovery> DISCOVERY = new BodyCodec<>(MessageType.DISCOVERY, Discovery.class,
            (m, w) -> {
                w.string8(m.mission());
                w.string8(m.role());
                w.i32(m.level());
                w.i64(m.epoch());
            },
            r -> new Discovery(r.name("mission"), r.name("role"), r.i32("level"), r.i64("epoch")));

    static final BodyCodec<DiscoveryReply> DISCOVERY_REPLY = new BodyCodec<>(MessageType.DISCOVERY_REPLY,
            DiscoveryReply.class,
            (m, w) -> {
                w.i64(m.inReplyTo());
                w.string8(m.mission());
                w.string8(m.holds());
                CapabilityBodies.writeSummary(m.summary(), w);
            },
            r -> new DiscoveryReply(r.i64("inReplyTo"), r.name("mission"), r.string8("holds", WireFormat.MAX_NAME),
                    CapabilityBodies.readSummary(r)));

    static final BodyCodec<CapabilityRequest> CAPABILITY_REQUEST = new BodyCodec<>(MessageType.CAPABILITY_REQUEST,
            CapabilityRequest.class,
            (m, w) -> w.string8(m.role()),
            r -> new CapabilityRequest(r.name("role")));

    static final BodyCodec<CapabilityReply> CAPABILITY_REPLY = new BodyCodec<>(MessageType.CAPABILITY_REPLY,
            CapabilityReply.class,
            (m, w) -> {
                w.i64(m.inReplyTo());
                CapabilityBodies.writeDescription(m.description(), w);
            },
            r -> new CapabilityReply(r.i64("inReplyTo"), CapabilityBodies.readDescription(r)));

    static final BodyCodec<RoleAssignment> ROLE_ASSIGNMENT = new BodyCodec<>(MessageType.ROLE_ASSIGNMENT,
            RoleAssignment.class,
            (m, w) -> {
                w.string8(m.mission());
                w.string8(m.role());
                w.i32(m.identity().level());
                w.i32(m.identity().sequence());
                w.string8(m.parent());
                w.u8(m.policies().size());
                for (PolicyRef p : m.policies()) {
                    w.string8(p.uri());
                    w.i32(p.version());
                }
                w.i64(m.epoch());
                ValueCodec.writeList(m.handover(), w);
                w.u8(m.keeps().size());
                for (String k : m.keeps()) {
                    w.string8(k);
                }
                writeNames(m.ancestors(), w);
            },
            TeamBodies::readRoleAssignment);

    static final BodyCodec<AssignmentResponse> ASSIGNMENT_RESPONSE = new BodyCodec<>(MessageType.ASSIGNMENT_RESPONSE,
            AssignmentResponse.class,
            (m, w) -> {
                w.i64(m.inReplyTo());
                w.string8(m.role());
                w.bool(m.accepted());
                w.string8(m.reason());
            },
            r -> new AssignmentResponse(r.i64("inReplyTo"), r.name("role"), r.bool("accepted"),
                    r.string8("reason", WireFormat.MAX_TEXT)));

    static final BodyCodec<Status> STATUS = new BodyCodec<>(MessageType.STATUS, Status.class,
            (m, w) -> {
                w.string8(m.mission());
                w.i32(m.identity().level());
                w.i32(m.identity().sequence());
                w.string8(m.commander());
                w.i64(m.epoch());
                w.i32(m.teamSize());
                w.i64(m.echo());
                writeNames(m.ancestors(), w);
                w.varint(m.version());
            },
            r -> {
                String mission = r.name("mission");
                Identity identity = new Identity(mission, r.i32("identity.level"), r.i32("identity.sequence"));
                return new Status(mission, identity, r.string8("commander", WireFormat.MAX_SENDER), r.i64("epoch"),
                        r.i32("teamSize"), r.i64("echo"), readNames(r, "ancestors"), r.varint("version"));
            });

    static final BodyCodec<Leave> LEAVE = new BodyCodec<>(MessageType.LEAVE, Leave.class,
            (m, w) -> w.string8(m.reason()),
            r -> new Leave(r.string8("reason", WireFormat.MAX_TEXT)));

    static final BodyCodec<Roster> ROSTER = new BodyCodec<>(MessageType.ROSTER, Roster.class,
            (m, w) -> {
                w.string8(m.mission());
                w.i64(m.epoch());
                w.u8(m.backups().size());
                for (String b : m.backups()) {
                    w.string8(b);
                }
                w.u16(m.members().size());
                for (Roster.Entry e : m.members()) {
                    w.string8(e.vehicle());
                    w.string8(e.address());
                    w.string8(e.role());
                    w.i32(e.slot());
                }
            },
            TeamBodies::readRoster);

    static final BodyCodec<Withdrawal> WITHDRAWAL = new BodyCodec<>(MessageType.WITHDRAWAL, Withdrawal.class,
            (m, w) -> {
                w.i64(m.inReplyTo());
                w.string8(m.mission());
            },
            r -> new Withdrawal(r.i64("inReplyTo"), r.name("mission")));

    static final List<BodyCodec<?>> ALL = List.of(DISCOVERY, DISCOVERY_REPLY, CAPABILITY_REQUEST, CAPABILITY_REPLY,
            ROLE_ASSIGNMENT, ASSIGNMENT_RESPONSE, STATUS, LEAVE, ROSTER, WITHDRAWAL);

    private static RoleAssignment readRoleAssignment(DatagramReader r) throws DecodeException {
        String mission = r.name("mission");
        String role = r.name("role");
        Identity identity = new Identity(mission, r.i32("identity.level"), r.i32("identity.sequence"));
        String parent = r.string8("parent", WireFormat.MAX_SENDER);
        int n = r.count("policies", WireFormat.MAX_POLICIES, 5);
        List<PolicyRef> policies = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            policies.add(new PolicyRef(r.string8("policy uri", WireFormat.MAX_URI), r.i32("policy version")));
        }
        long epoch = r.i64("epoch");
        List<Object> handover = ValueCodec.readList(r, "handover");
        int nk = r.count("keeps", RoleAssignment.MAX_KEEPS, 2);
        List<String> keeps = new ArrayList<>(nk);
        for (int i = 0; i < nk; i++) {
            keeps.add(r.string8("keep", WireFormat.MAX_NAME + 11));
        }
        return new RoleAssignment(mission, role, identity, parent, policies, epoch, handover, keeps,
                readNames(r, "ancestors"));
    }

    private static void writeNames(List<String> names, ByteWriter w) {
        w.u8(names.size());
        for (String n : names) {
            w.string8(n);
        }
    }

    private static List<String> readNames(DatagramReader r, String field) throws DecodeException {
        int n = r.count(field, RoleAssignment.MAX_ANCESTORS, 2);
        List<String> names = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            names.add(r.string8(field, WireFormat.MAX_SENDER));
        }
        return names;
    }

    private static Roster readRoster(DatagramReader r) throws DecodeException {
        String mission = r.name("mission");
        long epoch = r.i64("epoch");
        int nb = r.count("backups", Roster.MAX_BACKUPS, 1);
        List<String> backups = new ArrayList<>(nb);
        for (int i = 0; i < nb; i++) {
            backups.add(r.string8("backup", WireFormat.MAX_SENDER));
        }
        int nm = r.count16("members", Roster.MAX_MEMBERS, 4);
        List<Roster.Entry> members = new ArrayList<>(nm);
        for (int i = 0; i < nm; i++) {
            members.add(new Roster.Entry(r.string8("member.vehicle", WireFormat.MAX_SENDER),
                    r.string8("member.address", WireFormat.MAX_TEXT), r.name("member.role"), r.i32("member.slot")));
        }
        return new Roster(mission, epoch, backups, members);
    }
}
