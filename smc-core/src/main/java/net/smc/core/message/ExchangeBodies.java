package net.smc.core.message;

import java.util.List;

/**
 * Payloads of the messages of a running team: policies, heartbeats, acknowledgements (single and
 * coalesced), role events
 * and remote invocations. Fields follow each other in record order.
 */
final class ExchangeBodies {
    private ExchangeBodies() {
    }

    static final BodyCodec<PolicyRequest> POLICY_REQUEST = new BodyCodec<>(MessageType.POLICY_REQUEST,
            PolicyRequest.class,
            (m, w) -> {
                w.string8(m.uri());
                w.i32(m.version());
            },
            r -> new PolicyRequest(r.string8("uri", WireFormat.MAX_URI), r.i32("version")));

    static final BodyCodec<PolicyReply> POLICY_REPLY = new BodyCodec<>(MessageType.POLICY_REPLY, PolicyReply.class,
            (m, w) -> {
                w.i64(m.inReplyTo());
                w.string8(m.uri());
                w.i32(m.version());
                PolicyTextCoding.write(m.text(), w);
            },
            r -> new PolicyReply(r.i64("inReplyTo"), r.string8("uri", WireFormat.MAX_URI), r.i32("version"),
                    PolicyTextCoding.read(r, "text")));

    static final BodyCodec<Heartbeat> HEARTBEAT = new BodyCodec<>(MessageType.HEARTBEAT, Heartbeat.class,
            (m, w) -> {
                w.string8(m.role());
                w.varint(m.epoch());
                w.varint(m.state());
                w.varint(m.statusVersion());
            },
            r -> new Heartbeat(r.name("role"), r.varint("epoch"), intVarint(r, "state"), r.varint("statusVersion")));

    static final BodyCodec<Echo> ECHO = new BodyCodec<>(MessageType.ECHO, Echo.class,
            (m, w) -> w.i32((int) m.echo()),
            r -> new Echo(Integer.toUnsignedLong(r.i32("echo"))));

    static final BodyCodec<Ack> ACK = new BodyCodec<>(MessageType.ACK, Ack.class,
            (m, w) -> w.i64(m.acked()),
            r -> new Ack(r.i64("acked")));

    static final BodyCodec<Acks> ACKS = new BodyCodec<>(MessageType.ACKS, Acks.class,
            (m, w) -> {
                List<Long> ids = m.acked();
                w.u8(ids.size());
                for (int i = 0; i < ids.size(); i++) {
                    w.i64(ids.get(i));
                }
            },
            r -> {
                int n = r.count("acked", WireFormat.MAX_ACKS, 8);
                Long[] ids = new Long[n];
                for (int i = 0; i < n; i++) {
                    ids[i] = r.i64("acked");
                }
                return new Acks(java.util.Arrays.asList(ids));
            });

    static final BodyCodec<RoleEvent> ROLE_EVENT = new BodyCodec<>(MessageType.ROLE_EVENT, RoleEvent.class,
            (m, w) -> {
                w.string8(m.role());
                w.string8(m.event());
                ValueCodec.writeList(m.values(), w);
                w.string8(m.origin());
            },
            r -> new RoleEvent(r.name("role"), r.name("event"), ValueCodec.readList(r, "values"),
                    r.string8("origin", WireFormat.MAX_SENDER)));

    static final BodyCodec<SubtreeReport> SUBTREE_REPORT = new BodyCodec<>(MessageType.SUBTREE_REPORT,
            SubtreeReport.class,
            (m, w) -> {
                w.string8(m.role());
                ValueCodec.writeList(m.values(), w);
            },
            r -> new SubtreeReport(r.name("role"), ValueCodec.readList(r, "values")));

    static final BodyCodec<Invocation> INVOCATION = new BodyCodec<>(MessageType.INVOCATION, Invocation.class,
            (m, w) -> {
                w.string8(m.role());
                w.string8(m.operation());
                ValueCodec.writeList(m.args(), w);
                w.string8(m.caller());
                w.i64(m.call());
                w.string8(m.origin());
                w.string8(m.reply());
            },
            r -> new Invocation(r.name("role"), r.name("operation"), ValueCodec.readList(r, "args"),
                    r.string8("caller", WireFormat.MAX_NAME), r.i64("call"), r.string8("origin", WireFormat.MAX_SENDER),
                    r.string8("reply", WireFormat.MAX_TEXT)));

    static final BodyCodec<InvocationResult> INVOCATION_RESULT = new BodyCodec<>(MessageType.INVOCATION_RESULT,
            InvocationResult.class,
            (m, w) -> {
                w.i64(m.inReplyTo());
                w.bool(m.ok());
                if (m.ok()) {
                    ValueCodec.write(m.value(), w);
                } else {
                    w.string8(m.error());
                }
            },
            r -> {
                long inReplyTo = r.i64("inReplyTo");
                return r.bool("ok")
                        ? InvocationResult.ok(inReplyTo, ValueCodec.read(r, "value"))
                        : InvocationResult.failed(inReplyTo, r.string8("error", WireFormat.MAX_TEXT));
            });

    static final BodyCodec<CellRequest> CELL_REQUEST = new BodyCodec<>(MessageType.CELL_REQUEST, CellRequest.class,
            (m, w) -> {
                w.u8(m.kind().code());
                w.string8(m.cell());
                w.string8(m.path());
                w.string8(m.selector());
                w.string8(m.event());
                ValueCodec.writeList(m.values(), w);
                w.string8(m.caller());
                w.i64(m.call());
                w.string8(m.origin());
                w.string8(m.reply());
            },
            r -> {
                int code = r.u8("kind");
                CellRequest.Kind kind = CellRequest.Kind.of(code);
                if (kind == null) {
                    throw new DecodeException(RejectReason.MALFORMED, "CellRequest.kind is " + code
                            + "; it is 1 (event) or 2 (evaluate)");
                }
                return new CellRequest(kind, r.string8("cell", WireFormat.MAX_SENDER), r.string8("path", WireFormat.MAX_URI),
                        r.string8("selector", WireFormat.MAX_NAME), r.string8("event", WireFormat.MAX_NAME),
                        ValueCodec.readList(r, "values"), r.name("caller"), r.i64("call"),
                        r.string8("origin", WireFormat.MAX_SENDER), r.string8("reply", WireFormat.MAX_TEXT));
            });

    /** A varint that must fit an int (a heartbeat's state). */
    private static int intVarint(DatagramReader r, String field) throws DecodeException {
        long v = r.varint(field);
        if (v > Integer.MAX_VALUE) {
            throw new DecodeException(RejectReason.MALFORMED, field + " is " + v + "; at most " + Integer.MAX_VALUE);
        }
        return (int) v;
    }

    static final List<BodyCodec<?>> ALL = List.of(POLICY_REQUEST, POLICY_REPLY, HEARTBEAT, ECHO, ACK,
            ROLE_EVENT, INVOCATION, INVOCATION_RESULT, ACKS, SUBTREE_REPORT, CELL_REQUEST);
}
