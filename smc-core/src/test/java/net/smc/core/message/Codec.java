package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Arrays;
import java.util.List;

/** Test helpers around one encoder and one decoder on a virtual clock. */
final class Codec {
    final MessageEncoder encoder = new MessageEncoder();
    long now;
    final MessageDecoder decoder;

    Codec() {
        this(ReassemblySettings.DEFAULTS);
    }

    Codec(ReassemblySettings settings) {
        decoder = new MessageDecoder(() -> now, settings);
    }

    List<byte[]> encode(Envelope e) {
        return encoder.datagrams(e);
    }

    /** The single datagram of a message that fits one. */
    byte[] datagram(Envelope e) {
        List<byte[]> d = encode(e);
        assertEquals(1, d.size(), () -> e + " takes " + d.size() + " datagrams");
        return d.get(0);
    }

    DecodeResult decode(byte[] datagram) {
        return decoder.decode(datagram);
    }

    /** Decodes a message's datagrams in order and returns the envelope the last one completes. */
    Envelope roundTrip(Envelope e) {
        List<byte[]> datagrams = encode(e);
        for (int i = 0; i < datagrams.size() - 1; i++) {
            assertInstanceOf(DecodeResult.FragmentPending.class, decode(datagrams.get(i)));
        }
        return decoded(decode(datagrams.get(datagrams.size() - 1)));
    }

    static Envelope decoded(DecodeResult r) {
        if (r instanceof DecodeResult.Decoded d) {
            return d.envelope();
        }
        return fail("expected a decoded message, got " + r);
    }

    static DecodeResult.Rejected rejected(DecodeResult r) {
        if (r instanceof DecodeResult.Rejected rej) {
            return rej;
        }
        return fail("expected a rejection, got " + r);
    }

    /**
     * The invariants of any decode: never an internal error; a decoded single datagram re-encodes
     * to exactly its bytes (the format has one encoding per message), except a policy reply whose
     * text came as another deflater's stream, which must re-encode to the same message.
     */
    void checkInvariants(byte[] input, DecodeResult r) {
        checkInvariants(input, r, null);
    }

    /**
     * As {@link #checkInvariants(byte[], DecodeResult)}, for a decode given {@code namedSender} by
     * the transport (null: none): a datagram that leaves its sender out decodes with that sender and
     * re-encodes to its bytes when its type's sender is left to the transport.
     */
    void checkInvariants(byte[] input, DecodeResult r, String namedSender) {
        if (r instanceof DecodeResult.Rejected rej) {
            assertNotEquals(RejectReason.INTERNAL_ERROR, rej.reason(), rej.detail());
        } else if (r instanceof DecodeResult.Decoded d && input.length > 3 && (input[3] & 0xFF) != WireFormat.FRAGMENT_CODE) {
            boolean left = input.length > 4 && input[4] == 0;
            if (left && !d.envelope().sender().equals(namedSender)) {
                fail("decoded " + d.envelope() + " from a header without a sender, but the transport named " + namedSender);
            }
            MessageEncoder again0 = left
                    ? new MessageEncoder().leaveSenderToTransport(java.util.Set.of(d.envelope().type())) : encoder;
            List<byte[]> again = again0.datagrams(d.envelope());
            boolean same = again.size() == 1 && Arrays.equals(again.get(0), input);
            if (!same && d.envelope().body() instanceof PolicyReply) {
                byte[] first = again.get(0);
                same = d.envelope().equals(decoded(new Codec().decoder.decode(namedSender, first, 0, first.length)));
            }
            if (!same) {
                fail("decoded " + d.envelope() + " does not re-encode to its datagram");
            }
        }
    }
}
