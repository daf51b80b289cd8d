/**
 * The messages cells exchange and their binary codec.
 *
 * <p>{@link net.smc.core.message.Message} is a closed family of immutable records, one per
 * {@link net.smc.core.message.MessageType}, each checking its fields in its constructor; an
 * {@link net.smc.core.message.Envelope} adds the sender and the message id.
 * {@link net.smc.core.message.MessageEncoder} writes envelopes as datagrams of at most 1,400 bytes,
 * splitting large payloads into fragments; {@link net.smc.core.message.MessageDecoder} reads them
 * back, reassembles fragments under bounds of time and memory, and rejects anything else with a
 * counted {@link net.smc.core.message.RejectReason}. The codec is split by concern: the header,
 * field readers and writers, one payload codec per message type, the policy texts' compression
 * ({@code PolicyTextCoding}: deflated on the wire, inflated within bounds), the fragmenter and the
 * reassembler. The format and its limits are described in
 * <a href="doc-files/wire-format.md">the wire-format note</a> and {@link net.smc.core.message.WireFormat}.
 *
 * <pre>{@code
 * MessageEncoder encoder = new MessageEncoder();
 * MessageDecoder decoder = new MessageDecoder(clock::millis);
 * ByteBuffer buf = ByteBuffer.allocate(WireFormat.MAX_DATAGRAM);
 * encoder.encode(new Envelope("uav1", 7, new Heartbeat("relay", 3, 0)), buf);
 * DecodeResult r = decoder.decode(buf.flip());   // Decoded[envelope=Envelope[sender=uav1, ...]]
 * }</pre>
 */
package net.smc.core.message;
