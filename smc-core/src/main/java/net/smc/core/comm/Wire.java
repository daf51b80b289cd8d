package net.smc.core.comm;

import java.util.List;
import java.util.Set;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import net.smc.core.message.DecodeResult;
import net.smc.core.message.Envelope;
import net.smc.core.message.MessageDecoder;
import net.smc.core.message.MessageEncoder;
import net.smc.core.message.MessageType;
import net.smc.core.message.ReassemblySettings;
import net.smc.core.message.SharedDecodes;
import net.smc.core.transport.Address;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Transport;

/**
 * The cell's use of the codec and the transport: envelopes to datagrams and out, datagrams in to
 * envelopes. Decoding never throws: a datagram that is not a message is counted by reason and, at
 * debug level, logged with its source; a fragment is held by the decoder until its message is whole.
 */
final class Wire {
    private static final Logger log = LoggerFactory.getLogger(Wire.class);

    private final Transport transport;
    private final MessageEncoder encoder;
    private final MessageDecoder decoder;
    private final CommCounters counters;

    /** {@code senderLeft}: the types whose header leaves the sender to the transport (see {@link MessageEncoder#leaveSenderToTransport}). */
    Wire(Transport transport, Clock clock, ReassemblySettings reassembly, CommCounters counters, SharedDecodes shared,
            Set<MessageType> senderLeft) {
        this.transport = transport;
        this.encoder = new MessageEncoder(transport.datagramCapacity()).leaveSenderToTransport(senderLeft);
        this.decoder = new MessageDecoder(clock::nowMillis, reassembly).share(shared);
        this.counters = counters;
    }

    /** Encodes {@code envelope} into its datagrams (one, or fragment frames), which the caller may keep. */
    List<byte[]> encode(Envelope envelope) {
        return encoder.datagrams(envelope);
    }

    /** How long the transport's queue holds what is handed to it now ({@link Transport#backlogMillis()}). */
    long backlogMillis() {
        return transport.backlogMillis();
    }

    void send(Address to, List<byte[]> datagrams) {
        for (byte[] d : datagrams) {
            transport.send(to, d);
            counters.datagramsSent++;
        }
    }

    /** As {@link #send}, starting no session on an authenticating transport ({@code AuthenticatingTransport.sendWithoutHandshake}). */
    void sendWithoutHandshake(Address to, List<byte[]> datagrams) {
        if (!(transport instanceof net.smc.core.security.AuthenticatingTransport auth)) {
            send(to, datagrams);
            return;
        }
        for (byte[] d : datagrams) {
            auth.sendWithoutHandshake(to, d);
            counters.datagramsSent++;
        }
    }

    void broadcast(List<byte[]> datagrams) {
        for (byte[] d : datagrams) {
            transport.broadcast(d);
            counters.datagramsSent++;
        }
    }

    /**
     * The message in {@code data}, or null when it was rejected or is a fragment of one not yet whole;
     * {@code proven} is the sender the transport proved (null on a plain transport), the sender of a
     * header that leaves it out.
     */
    Envelope decode(String proven, Address from, byte[] data) {
        counters.datagramsReceived++;
        DecodeResult result = decoder.decode(proven, data, 0, data.length);
        if (result instanceof DecodeResult.Decoded d) {
            return d.envelope();
        }
        if (result instanceof DecodeResult.FragmentPending) {
            counters.fragmentsHeld++;
            return null;
        }
        DecodeResult.Rejected r = (DecodeResult.Rejected) result;
        counters.rejected[r.reason().ordinal()]++;
        if (log.isDebugEnabled()) {
            log.debug("{}: datagram of {} bytes from {} rejected, {}: {}", transport.localAddress(), data.length, from,
                    r.reason(), r.detail());
        }
        return null;
    }
}
