package net.smc.core.message;

import java.nio.ByteBuffer;
import java.util.Objects;
import java.util.function.LongSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Turns datagrams in the <a href="doc-files/wire-format.md">wire format</a> into envelopes,
 * reassembling fragmented messages on the way.
 *
 * <p>Datagrams come from anyone, so {@link #decode} trusts nothing: it checks the size, the header,
 * every length (against the field's limit and against the bytes that remain, before allocating)
 * and every value, and it never throws: it returns a {@link DecodeResult}, counting each rejection
 * by its {@link RejectReason} and logging it at debug level. A decoded message is exactly what its
 * bytes say: encoding it again gives the same bytes.
 *
 * <p>Time comes from the injected clock (milliseconds, monotonic; a virtual clock in simulation),
 * used only to expire reassemblies, which happens on every decode while any is in progress and on
 * {@link #expire()}. A decoder keeps per-datagram state and is not thread-safe: one per cell.
 */
public final class MessageDecoder {
    private static final Logger log = LoggerFactory.getLogger(MessageDecoder.class);

    private final LongSupplier clock;
    private final Reassembler reassembler;
    private final DatagramReader reader = new DatagramReader();
    private final Header header = new Header();
    /** A copy of a datagram that arrived in a buffer without an accessible array; made when first needed. */
    private byte[] copy;
    private final long[] rejected = new long[RejectReason.values().length];
    private long decoded;
    private long pending;
    /** The type of the message whose reassembled payload is being read, else null. */
    private MessageType reassembled;
    /** Decodes shared with the other cells of the process, or null. */
    private SharedDecodes shared;

    /** A decoder with {@link ReassemblySettings#DEFAULTS}. */
    public MessageDecoder(LongSupplier clockMillis) {
        this(clockMillis, ReassemblySettings.DEFAULTS);
    }

    public MessageDecoder(LongSupplier clockMillis, ReassemblySettings settings) {
        if (clockMillis == null || settings == null) {
            throw new IllegalArgumentException("clockMillis and settings are required; got " + clockMillis + ", "
                    + settings);
        }
        this.clock = clockMillis;
        this.reassembler = new Reassembler(settings);
    }

    /**
     * Shares decodes of broadcast datagrams with the other decoders given the same table (see
     * {@link SharedDecodes}); null stops sharing. A shared decode counts as decoded here.
     */
    public MessageDecoder share(SharedDecodes table) {
        this.shared = table;
        return this;
    }

    /** Decodes the datagram between the buffer's position and limit; the buffer is left unchanged. */
    public DecodeResult decode(ByteBuffer datagram) {
        int length = datagram.remaining();
        if (datagram.hasArray()) {
            return decode(datagram.array(), datagram.arrayOffset() + datagram.position(), length);
        }
        if (length > WireFormat.MAX_DATAGRAM) {
            return reject(RejectReason.OVERSIZED, tooLarge(length));
        }
        if (copy == null) {
            copy = new byte[WireFormat.MAX_DATAGRAM];
        }
        datagram.get(datagram.position(), copy, 0, length);
        return decode(copy, 0, length);
    }

    /** Decodes a whole array as one datagram. */
    public DecodeResult decode(byte[] datagram) {
        return decode(datagram, 0, datagram.length);
    }

    /**
     * Decodes {@code data[offset, offset + length)} as one datagram. The array is only read, and
     * not kept.
     *
     * @throws IndexOutOfBoundsException if the range is not inside the array (a caller's bug, not bad input)
     */
    public DecodeResult decode(byte[] data, int offset, int length) {
        return decode(null, data, offset, length);
    }

    /**
     * Decodes {@code data[offset, offset + length)} as one datagram that came over a transport
     * naming its sender {@code namedSender} (proven by an authenticating transport; null when the
     * transport names none): a header that leaves its sender out takes this one, and one that names
     * its own keeps it (the caller compares the two). The array is only read, and not kept.
     *
     * @throws IndexOutOfBoundsException if the range is not inside the array (a caller's bug, not bad input)
     */
    public DecodeResult decode(String namedSender, byte[] data, int offset, int length) {
        Objects.checkFromIndexSize(offset, length, data.length);
        header.sender = null;
        reassembled = null;
        try {
            if (reassembler.inProgress() > 0) {
                reassembler.expire(clock.getAsLong());
            }
            if (length > WireFormat.MAX_DATAGRAM) {
                throw new DecodeException(RejectReason.OVERSIZED, tooLarge(length));
            }
            // only a datagram that names its sender is a function of its bytes alone
            boolean sharing = shared != null && length > WireFormat.FIXED_HEADER && SharedDecodes.keeps(data[offset + 3] & 0xFF)
                    && data[offset + 4] != 0;
            if (sharing) {
                DecodeResult.Decoded known = shared.find(data, offset, length);
                if (known != null) {
                    decoded++;
                    return known;
                }
            }
            reader.reset(data, offset, offset + length);
            header.read(reader, namedSender);
            if (header.typeCode == WireFormat.FRAGMENT_CODE) {
                return fragment();
            }
            DecodeResult result = decoded(MessageType.byCode(header.typeCode));
            if (sharing && result instanceof DecodeResult.Decoded d) {
                shared.keep(data, offset, length, d);
            }
            return result;
        } catch (DecodeException e) {
            return reject(e.reason(), context(length) + e.getMessage());
        } catch (RuntimeException e) {
            log.warn("decoder failed on a datagram of {} bytes", length, e);
            return reject(RejectReason.INTERNAL_ERROR, context(length) + e);
        }
    }

    /** Drops reassemblies whose time is up; call it from a timer if datagrams may stop arriving. */
    public void expire() {
        reassembler.expire(clock.getAsLong());
    }

    private DecodeResult fragment() throws DecodeException {
        FragmentHeader f = FragmentHeader.read(reader);
        Reassembler.Progress progress = reassembler.accept(header.sender, header.id, f, reader.array(),
                reader.position(), clock.getAsLong());
        if (progress.payload() == null) {
            pending++;
            return new DecodeResult.FragmentPending(header.sender, header.id, f.type(), progress.received(), f.count());
        }
        reassembled = f.type();
        reader.reset(progress.payload(), 0, progress.payload().length);
        return decoded(f.type());
    }

    /** Reads the payload at the reader as a {@code type} message; the records' constructors judge the fields. */
    private DecodeResult decoded(MessageType type) throws DecodeException {
        Envelope envelope;
        try {
            Message body = BodyCodec.of(type).read(reader);
            reader.end();
            envelope = new Envelope(header.sender, header.id, body);
        } catch (IllegalArgumentException e) {
            throw new DecodeException(RejectReason.INVALID_FIELD, e.getMessage());
        }
        decoded++;
        return new DecodeResult.Decoded(envelope);
    }

    private DecodeResult reject(RejectReason reason, String detail) {
        rejected[reason.ordinal()]++;
        if (log.isDebugEnabled()) {
            log.debug("discarded datagram ({}): {}", reason, detail);
        }
        return new DecodeResult.Rejected(reason, detail);
    }

    private String context(int length) {
        if (header.sender == null) {
            return "datagram of " + length + " bytes: ";
        }
        String type = reassembled != null ? "reassembled " + reassembled : header.typeName();
        return type + " from '" + header.sender + "' (id " + header.id + "): ";
    }

    private static String tooLarge(int length) {
        return "datagram is " + length + " bytes; at most " + WireFormat.MAX_DATAGRAM + " are allowed";
    }

    /** Messages decoded (single datagrams and reassembled ones). */
    public long decoded() {
        return decoded;
    }

    /** Fragments stored while their message is incomplete. */
    public long fragmentsPending() {
        return pending;
    }

    /** Datagrams rejected for {@code reason}. */
    public long rejected(RejectReason reason) {
        return rejected[reason.ordinal()];
    }

    /** Datagrams rejected for any reason. */
    public long rejected() {
        long sum = 0;
        for (long n : rejected) {
            sum += n;
        }
        return sum;
    }

    /** Messages being reassembled now. */
    public int reassembliesInProgress() {
        return reassembler.inProgress();
    }

    /** Fragment bytes held now. */
    public long bufferedBytes() {
        return reassembler.bufferedBytes();
    }

    /** Reassemblies dropped because their time was up. */
    public long reassembliesExpired() {
        return reassembler.expired();
    }

    /** Reassemblies dropped to make room for others. */
    public long reassembliesEvicted() {
        return reassembler.evicted();
    }
}
