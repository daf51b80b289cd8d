package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class ReassemblyTest {
    private final Codec codec = new Codec(new ReassemblySettings(1_000, WireFormat.MAX_PAYLOAD, 3));

    /** A message of about {@code bytes} bytes, fragmented as it is (not compressed). */
    private static Envelope policy(String sender, long id, int bytes) {
        return new Envelope(sender, id, Samples.bulk("p" + id, bytes));
    }

    private DecodeResult.FragmentPending pending(byte[] datagram) {
        return assertInstanceOf(DecodeResult.FragmentPending.class, codec.decode(datagram));
    }

    @Test
    void fragmentsInAnyOrder_reassemble() {
        Envelope e = policy("uav1", 1, 20_000);
        Random random = new Random(3);
        for (int round = 0; round < 20; round++) {
            List<byte[]> fragments = new ArrayList<>(codec.encode(e));
            Collections.shuffle(fragments, random);
            for (int i = 0; i < fragments.size() - 1; i++) {
                assertEquals(i + 1, pending(fragments.get(i)).received());
            }
            assertEquals(e, Codec.decoded(codec.decode(fragments.get(fragments.size() - 1))));
        }
        assertEquals(0, codec.decoder.bufferedBytes());
    }

    @Test
    void pendingResult_namesTheMessage() {
        DecodeResult.FragmentPending p = pending(codec.encode(policy("uav1", 9, 5_000)).get(2));
        assertEquals(new DecodeResult.FragmentPending("uav1", 9, MessageType.ROLE_EVENT, 1, 4), p);
    }

    @Test
    void duplicateFragment_isRejectedAndTheMessageStillCompletes() {
        Envelope e = policy("uav1", 1, 5_000);
        List<byte[]> fragments = codec.encode(e);
        pending(fragments.get(0));
        DecodeResult.Rejected r = Codec.rejected(codec.decode(fragments.get(0)));
        assertEquals(RejectReason.DUPLICATE_FRAGMENT, r.reason());
        assertEquals("FRAGMENT from 'uav1' (id 1): fragment 0 of 4 is already held", r.detail());
        for (int i = 1; i < fragments.size() - 1; i++) {
            pending(fragments.get(i));
        }
        assertEquals(e, Codec.decoded(codec.decode(fragments.get(fragments.size() - 1))));
        assertEquals(1, codec.decoder.rejected(RejectReason.DUPLICATE_FRAGMENT));
    }

    @Test
    void messagesFromDifferentSendersWithTheSameId_doNotMix() {
        Envelope a = policy("uav1", 1, 3_000);
        Envelope b = policy("uav2", 1, 3_000);
        List<byte[]> fa = codec.encode(a);
        List<byte[]> fb = codec.encode(b);
        pending(fa.get(0));
        pending(fb.get(0));
        pending(fa.get(1));
        pending(fb.get(1));
        assertEquals(a, Codec.decoded(codec.decode(fa.get(2))));
        assertEquals(b, Codec.decoded(codec.decode(fb.get(2))));
    }

    @Test
    void missingFragment_expiresOnTheInjectedClock() {
        List<byte[]> fragments = codec.encode(policy("uav1", 1, 5_000));
        pending(fragments.get(0));
        pending(fragments.get(1));
        codec.now = 999;
        codec.decode(codec.datagram(new Envelope("uav3", 1, new Ack(1))));
        assertEquals(1, codec.decoder.reassembliesInProgress(), "not yet");
        codec.now = 1_000;
        codec.decoder.expire();
        assertEquals(0, codec.decoder.reassembliesInProgress());
        assertEquals(0, codec.decoder.bufferedBytes());
        assertEquals(1, codec.decoder.reassembliesExpired());
        // A late fragment starts over and cannot complete the expired message.
        assertEquals(1, pending(fragments.get(3)).received());
    }

    @Test
    void expiry_runsOnAnyDecodeWhileReassembliesWait() {
        pending(codec.encode(policy("uav1", 1, 5_000)).get(0));
        codec.now = 5_000;
        codec.decode(new byte[0]);
        assertEquals(0, codec.decoder.reassembliesInProgress());
        assertEquals(1, codec.decoder.reassembliesExpired());
    }

    @Test
    void expiry_countsFromTheFirstFragmentNotTheLatest() {
        List<byte[]> fragments = codec.encode(policy("uav1", 1, 5_000));
        pending(fragments.get(0));
        codec.now = 900;
        pending(fragments.get(1));
        codec.now = 1_000;
        codec.decoder.expire();
        assertEquals(0, codec.decoder.reassembliesInProgress(), "a trickle of fragments must not keep it alive");
    }

    @Test
    void byteBound_evictsTheOldestReassembly() {
        // Two messages of 40 KB do not fit the 65,535-byte bound together.
        List<byte[]> a = codec.encode(policy("uav1", 1, 40_000));
        List<byte[]> b = codec.encode(policy("uav1", 2, 40_000));
        for (int i = 0; i < a.size() - 1; i++) {
            pending(a.get(i));
        }
        for (int i = 0; i < b.size() - 1; i++) {
            pending(b.get(i));
        }
        assertEquals(1, codec.decoder.reassembliesEvicted());
        assertEquals(1, codec.decoder.reassembliesInProgress());
        Codec.decoded(codec.decode(b.get(b.size() - 1)));
        // The evicted one starts over from its last fragment.
        assertEquals(1, pending(a.get(a.size() - 1)).received());
    }

    @Test
    void byteBound_holdsAtEveryStep() {
        Random random = new Random(11);
        List<byte[]> all = new ArrayList<>();
        for (int id = 0; id < 8; id++) {
            all.addAll(codec.encode(policy("uav" + id % 3, id, 5_000 + random.nextInt(30_000))));
        }
        Collections.shuffle(all, random);
        for (byte[] d : all) {
            codec.decode(d);
            assertTrue(codec.decoder.bufferedBytes() <= WireFormat.MAX_PAYLOAD);
            assertTrue(codec.decoder.reassembliesInProgress() <= 3);
        }
    }

    @Test
    void reassemblyBound_evictsTheOldest() {
        List<List<byte[]>> messages = new ArrayList<>();
        for (int id = 1; id <= 4; id++) {
            messages.add(codec.encode(policy("uav1", id, 3_000)));
            pending(messages.get(id - 1).get(0));
        }
        assertEquals(3, codec.decoder.reassembliesInProgress());
        assertEquals(1, codec.decoder.reassembliesEvicted());
        // Message 1 was the oldest: its second fragment starts a new reassembly, evicting message 2.
        assertEquals(1, pending(messages.get(0).get(1)).received());
        assertEquals(2, codec.decoder.reassembliesEvicted());
    }

    @Test
    void settings_refuseABufferSmallerThanOneMessage() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new ReassemblySettings(1_000, 1_000, 3));
        assertEquals("maxBufferedBytes is 1000; it must be at least 65535 (the largest message)", e.getMessage());
    }

    @Test
    void settings_refuseAZeroExpiry() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new ReassemblySettings(0, WireFormat.MAX_PAYLOAD, 3));
        assertEquals("expiryMillis is 0; it must be 1 ms or more", e.getMessage());
    }
}
