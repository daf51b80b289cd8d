package net.smc.core.security;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import net.smc.core.transport.Transport;
import org.junit.jupiter.api.Test;

/**
 * Hostile bytes never throw out of {@code unwrap}: random datagrams, every truncation of a genuine
 * datagram of each kind, and random corruptions of them (seeded, thousands in all). Each is refused
 * and counted; none is delivered; the endpoint still works afterwards.
 */
class UnwrapRobustnessTest {
    private static final long SEED = 20_240_611L;

    private final Team team = new Team(6);
    private final SecureEndpoint a = team.endpoint("uav-a");
    private final SecureEndpoint b = team.endpoint("uav-b");
    private final byte[] payload = "HB seq=1".getBytes(StandardCharsets.UTF_8);

    /** One genuine datagram of each kind from a to b; b is ready to accept each of them. */
    private List<byte[]> genuine() {
        Team.shakeHands(a, b);
        a.newTeamKey();
        List<byte[]> out = new ArrayList<>();
        out.add(a.wrapSigned(payload));
        out.add(a.startHandshake("uav-b"));
        out.add(a.wrapFor("uav-b", payload));
        out.add(a.wrapTeamKey("uav-b"));
        b.unwrap(out.get(3));
        out.add(a.wrapTeam(payload));
        return out;
    }

    private static void refuse(SecureEndpoint to, byte[] datagram, String what) {
        Unwrapped u;
        try {
            u = to.unwrap(datagram);
        } catch (RuntimeException e) {
            throw new AssertionError("unwrap threw for " + what + ": " + Arrays.toString(datagram), e);
        }
        if (!(u instanceof Unwrapped.Rejected)) {
            fail("not refused: " + what + " -> " + u);
        }
    }

    @Test
    void randomDatagrams_areRefusedAsMalformedOrWorse_neverThrow() {
        SplittableRandom random = new SplittableRandom(SEED);
        genuine();
        long before = b.counters().unwrapped();
        int n = 3_000;
        for (int i = 0; i < n; i++) {
            byte[] datagram = new byte[random.nextInt(Transport.MAX_DATAGRAM_BYTES + 1)];
            random.nextBytes(datagram);
            if (datagram.length >= 2 && random.nextBoolean()) {
                datagram[0] = (byte) FrameCodec.VERSION;            // a known version, so parsing goes deeper
                datagram[1] = (byte) (1 + random.nextInt(5));      // a known kind
            }
            refuse(b, datagram, "random datagram " + i);
        }
        assertEquals(before + n, b.counters().unwrapped(), "every input is counted once");
    }

    @Test
    void everyTruncationOfEveryKind_isRefused() {
        List<byte[]> genuine = genuine();
        long before = b.counters().rejectedTotal();
        int inputs = 0;
        for (byte[] datagram : genuine) {
            for (int length = 0; length < datagram.length; length++) {
                refuse(b, Arrays.copyOf(datagram, length), "kind " + datagram[1] + " cut to " + length + " bytes");
                inputs++;
            }
        }
        assertEquals(genuine.stream().mapToInt(d -> d.length).sum(), inputs);
        assertEquals(before + inputs, b.counters().rejectedTotal());
    }

    @Test
    void corruptedDatagramsOfEveryKind_areRefused() {
        SplittableRandom random = new SplittableRandom(SEED + 1);
        List<byte[]> genuine = genuine();
        for (int i = 0; i < 2_000; i++) {
            byte[] datagram = genuine.get(i % genuine.size()).clone();
            int at = random.nextInt(datagram.length);
            switch (random.nextInt(4)) {
                case 0 -> datagram[at] ^= (byte) (1 << random.nextInt(8));        // one bit
                case 1 -> datagram[at] = (byte) random.nextInt(256);               // one byte
                case 2 -> datagram[at] = (byte) (random.nextBoolean() ? 0 : 255); // a length to an extreme
                default -> datagram = grow(datagram, at, random);                 // bytes inserted
            }
            if (Arrays.equals(datagram, genuine.get(i % genuine.size()))) {
                continue;   // a byte replaced by itself
            }
            refuse(b, datagram, "corruption " + i + " of kind " + genuine.get(i % genuine.size())[1]);
        }
    }

    @Test
    void afterThousandsOfRefusals_genuineTrafficStillPasses() {
        SplittableRandom random = new SplittableRandom(SEED + 2);
        genuine();
        for (int i = 0; i < 1_000; i++) {
            byte[] datagram = new byte[random.nextInt(200)];
            random.nextBytes(datagram);
            b.unwrap(datagram);
        }

        assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(a.wrapFor("uav-b", payload)));
        assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(a.wrapTeam(payload)));
        assertInstanceOf(Unwrapped.Delivered.class, b.unwrap(a.wrapSigned(payload)));
    }

    private static byte[] grow(byte[] datagram, int at, SplittableRandom random) {
        byte[] extra = new byte[1 + random.nextInt(8)];
        random.nextBytes(extra);
        byte[] out = new byte[datagram.length + extra.length];
        System.arraycopy(datagram, 0, out, 0, at);
        System.arraycopy(extra, 0, out, at, extra.length);
        System.arraycopy(datagram, at, out, at + extra.length, datagram.length - at);
        return out;
    }
}
