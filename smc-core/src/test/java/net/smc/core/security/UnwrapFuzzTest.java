package net.smc.core.security;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;

/**
 * Fuzz target for the receiving side of the security layer: a genuine datagram of one of the five
 * kinds, edited (bytes set, cut, grown) or replaced by raw bytes, taken with the receiver's clock
 * where the sender's was, moved about the freshness window's edges, or moved by up to two days
 * either way (so that the counter's low bits are read round a clock far from the sender's). In the normal test run Jazzer replays the seeds in
 * {@code UnwrapFuzzTestInputs/unwrap/} (test resources); fuzz for real with
 * {@code ./gradlew :smc-core:test -Pfuzz=1 -Ptests='.*UnwrapFuzzTest'}. A finding is an exception
 * out of {@code unwrap}, an edited datagram delivered, a refusal that changed the receiver's state, or
 * an input counted other than once.
 */
class UnwrapFuzzTest {
    private static final long TWO_DAYS = 2 * 24 * Team.HOUR;
    private static final long WINDOW = SecuritySettings.DEFAULTS.freshnessWindowMillis();

    @FuzzTest(maxDuration = "2m")
    void unwrap(FuzzedDataProvider data) {
        Team team = new Team(9);
        SecureEndpoint a = team.endpoint("uav-a");
        SecureEndpoint b = team.endpoint("uav-b");
        byte[] payload = "HB seq=1".getBytes(StandardCharsets.UTF_8);
        Team.shakeHands(a, b);
        a.newTeamKey();
        b.unwrap(a.wrapTeamKey("uav-b"));
        List<byte[]> genuine = List.of(a.wrapSigned(payload), a.startHandshake("uav-b"), a.wrapFor("uav-b", payload),
                a.wrapTeamKey("uav-b"), a.wrapTeam(payload));

        byte[] original = genuine.get(data.consumeInt(0, genuine.size() - 1));
        byte[] datagram = data.consumeBoolean() ? data.consumeBytes(data.consumeInt(0, 1_500)) : edit(original, data);
        switch (data.consumeInt(0, 2)) {
            case 0 -> { }                                                             // the sender's clock
            case 1 -> team.clock.advance(data.consumeLong(-WINDOW - 10_000, WINDOW + 10_000)); // about the window's edges
            default -> team.clock.advance(data.consumeLong(-TWO_DAYS, TWO_DAYS));     // far: the low bits read round another clock
        }

        String before = Team.state(b);
        long unwrapped = b.counters().unwrapped();
        Unwrapped u;
        try {
            u = b.unwrap(datagram);
        } catch (RuntimeException e) {
            throw new AssertionError("unwrap threw for " + Arrays.toString(datagram), e);
        }
        if (b.counters().unwrapped() != unwrapped + 1) {
            throw new AssertionError("an input counted " + (b.counters().unwrapped() - unwrapped) + " times");
        }
        boolean untouched = genuine.stream().anyMatch(g -> Arrays.equals(g, datagram));
        if (!(u instanceof Unwrapped.Rejected) && !untouched) {
            throw new AssertionError("an edited datagram passed: " + u + " from " + Arrays.toString(datagram));
        }
        if (u instanceof Unwrapped.Rejected && !before.equals(Team.state(b))) {
            throw new AssertionError("a refusal changed the receiver: " + u);
        }
    }

    /** {@code original} with up to eight edits: a byte set, the end cut, or bytes inserted. */
    private static byte[] edit(byte[] original, FuzzedDataProvider data) {
        byte[] d = original.clone();
        int edits = data.consumeInt(1, 8);
        for (int i = 0; i < edits && d.length > 0; i++) {
            int at = data.consumeInt(0, d.length - 1);
            switch (data.consumeInt(0, 2)) {
                case 0 -> d[at] = data.consumeByte();
                case 1 -> d = Arrays.copyOf(d, at);
                default -> {
                    byte[] extra = data.consumeBytes(data.consumeInt(1, 8));
                    byte[] grown = new byte[d.length + extra.length];
                    System.arraycopy(d, 0, grown, 0, at);
                    System.arraycopy(extra, 0, grown, at, extra.length);
                    System.arraycopy(d, at, grown, at + extra.length, d.length - at);
                    d = grown;
                }
            }
        }
        return d;
    }
}
