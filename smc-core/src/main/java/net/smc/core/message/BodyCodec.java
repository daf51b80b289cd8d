package net.smc.core.message;

import java.util.ArrayList;
import java.util.List;
import net.smc.core.wire.ByteWriter;

/**
 * The payload codec of one message type: how its record's fields follow each other on the wire.
 * The codecs of all types are found in one place, {@link #of(MessageType)}, filled from
 * {@link TeamBodies} and {@link ExchangeBodies}; a type without a codec stops the class from loading.
 */
final class BodyCodec<M extends Message> {
    @FunctionalInterface
    interface Writer<M> {
        void write(M message, ByteWriter w);
    }

    @FunctionalInterface
    interface Reader<M> {
        /** Reads the fields and builds the record, whose constructor may refuse them. */
        M read(DatagramReader r) throws DecodeException;
    }

    private static final BodyCodec<?>[] BY_TYPE = register();

    final MessageType type;
    private final Class<M> recordClass;
    private final Writer<M> writer;
    private final Reader<M> reader;

    BodyCodec(MessageType type, Class<M> recordClass, Writer<M> writer, Reader<M> reader) {
        this.type = type;
        this.recordClass = recordClass;
        this.writer = writer;
        this.reader = reader;
    }

    static BodyCodec<?> of(MessageType type) {
        return BY_TYPE[type.ordinal()];
    }

    void write(Message message, ByteWriter w) {
        writer.write(recordClass.cast(message), w);
    }

    Message read(DatagramReader r) throws DecodeException {
        return reader.read(r);
    }

    private static BodyCodec<?>[] register() {
        List<BodyCodec<?>> all = new ArrayList<>(TeamBodies.ALL);
        all.addAll(ExchangeBodies.ALL);
        BodyCodec<?>[] byType = new BodyCodec<?>[MessageType.values().length];
        for (BodyCodec<?> c : all) {
            if (byType[c.type.ordinal()] != null) {
                throw new ExceptionInInitializerError("two codecs for " + c.type);
            }
            byType[c.type.ordinal()] = c;
        }
        for (MessageType t : MessageType.values()) {
            if (byType[t.ordinal()] == null) {
                throw new ExceptionInInitializerError("no codec for " + t);
            }
        }
        return byType;
    }
}
