package net.smc.core.message;

import java.util.List;

/**
 * A request of a standard object of one cell to another cell of the team, addressed by vehicle
 * (PonderTalk's {@code /team/<cell>/<path>}): an event an {@code EventForwarder} forwards to a
 * domain there, or PonderTalk text a remote {@code PonderTalk} sends to be evaluated there. Cells
 * pass it towards {@link #cell()}; that cell runs it under its authorisation policies with the
 * caller's role as the subject and answers with an {@link InvocationResult} whose
 * {@code inReplyTo} is {@link #call()}.
 *
 * @param kind     what is asked
 * @param cell     the vehicle whose cell is asked
 * @param path     {@link Kind#EVENT}: the domain's path below that cell's root; {@link Kind#EVALUATE}: empty
 * @param selector {@link Kind#EVENT}: empty to raise the event at the domain, else the one-argument
 *                 message to send it with; {@link Kind#EVALUATE}: {@code execute:} or {@code test:}
 * @param event    {@link Kind#EVENT}: the event template's name under {@code root/event}; else empty
 * @param values   {@link Kind#EVENT}: one map of the event's attributes; {@link Kind#EVALUATE}: the text
 * @param caller   the role the calling cell acts in
 * @param call     the caller's number for the request, 1 or more
 * @param origin   the calling vehicle; empty means the sender of the envelope
 * @param reply    where the answer goes ({@code host:port}); empty means back to the sender
 */
public record CellRequest(Kind kind, String cell, String path, String selector, String event, List<Object> values,
                          String caller, long call, String origin, String reply) implements Message {

    /** What a {@link CellRequest} asks; the code is its wire form. */
    public enum Kind {
        EVENT(1), EVALUATE(2);

        private final int code;

        Kind(int code) {
            this.code = code;
        }

        public int code() {
            return code;
        }

        /** The kind with this code, or null. */
        public static Kind of(int code) {
            for (Kind k : values()) {
                if (k.code == code) {
                    return k;
                }
            }
            return null;
        }
    }

    public CellRequest {
        Fields.present("CellRequest.kind", kind);
        Fields.string("CellRequest.cell", cell, 1, WireFormat.MAX_SENDER, "a vehicle id");
        Fields.string("CellRequest.path", path, 0, WireFormat.MAX_URI, "a path below the cell's root");
        Fields.string("CellRequest.selector", selector, 0, WireFormat.MAX_NAME, "a selector, or empty");
        Fields.string("CellRequest.event", event, 0, WireFormat.MAX_NAME, "an event name, or empty");
        values = ValueLimits.list("CellRequest.values", values);
        if (values.size() != 1) {
            throw new IllegalArgumentException("CellRequest.values has " + values.size()
                    + " values; it carries exactly one (the event's attributes, or the text)");
        }
        if (kind == Kind.EVENT && (path.isEmpty() || event.isEmpty())) {
            throw new IllegalArgumentException("CellRequest of kind EVENT needs a path and an event; got path '" + path
                    + "', event '" + event + "'");
        }
        if (kind == Kind.EVALUATE && !(values.get(0) instanceof String)) {
            throw new IllegalArgumentException("CellRequest of kind EVALUATE carries its text as a string; got "
                    + values.get(0));
        }
        Fields.name("CellRequest.caller", caller);
        if (call < 1) {
            throw new IllegalArgumentException("CellRequest.call is " + call + "; it must be 1 or more");
        }
        Fields.string("CellRequest.origin", origin, 0, WireFormat.MAX_SENDER, "a vehicle id, or empty for the sender");
        Fields.text("CellRequest.reply", reply);
    }

    /** The calling vehicle: {@link #origin()}, or {@code sender} when that is empty. */
    public String originOr(String sender) {
        return origin.isEmpty() ? sender : origin;
    }

    /** The same request, passed on by a cell on the way, naming the original caller. */
    public CellRequest via(String originVehicle) {
        return new CellRequest(kind, cell, path, selector, event, values, caller, call, originVehicle, reply);
    }

    @Override
    public MessageType type() {
        return MessageType.CELL_REQUEST;
    }
}
