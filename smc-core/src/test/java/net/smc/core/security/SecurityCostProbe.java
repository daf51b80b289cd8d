package net.smc.core.security;

import java.util.Locale;

/**
 * A rough, one-off measure of what authentication costs per message (not a test, not a benchmark
 * harness: no JMH until the project adds it here). Run it from the test classpath:
 *
 * <pre>{@code
 * ./gradlew :smc-core:testClasses
 * java -cp smc-core/build/classes/java/main:smc-core/build/classes/java/test:smc-policy/build/classes/java/main:SLF4J_API_JAR \
 *     net.smc.core.security.SecurityCostProbe
 * }</pre>
 *
 * It reports the mean time per operation after a warm-up, on one thread. The figure that matters is
 * the pair-MAC unwrap of a heartbeat-sized message (goal: at most 2 µs).
 */
public final class SecurityCostProbe {
    private static final int HEARTBEAT_BYTES = 48;

    private SecurityCostProbe() {
    }

    public static void main(String[] args) {
        Team team = new Team(99);
        SecureEndpoint a = team.endpoint("uav-17");
        SecureEndpoint b = team.endpoint("cmdr");
        Team.shakeHands(a, b);
        a.newTeamKey();
        b.unwrap(a.wrapTeamKey("cmdr"));
        byte[] heartbeat = new byte[HEARTBEAT_BYTES];
        int n = 200_000;

        for (int round = 0; round < 3; round++) {
            System.out.println("round " + (round + 1) + " (heartbeat payload " + HEARTBEAT_BYTES + " bytes, pair-MAC datagram "
                    + a.wrapFor("cmdr", heartbeat).length + " bytes)");
            byte[][] macd = new byte[n][];
            long t0 = System.nanoTime();
            for (int i = 0; i < n; i++) {
                macd[i] = a.wrapFor("cmdr", heartbeat);
            }
            report("pair-MAC wrap", System.nanoTime() - t0, n);
            t0 = System.nanoTime();
            int delivered = 0;
            for (int i = 0; i < n; i++) {
                delivered += b.unwrap(macd[i]) instanceof Unwrapped.Delivered ? 1 : 0;
            }
            report("pair-MAC unwrap (parse, MAC, credential time, window, copy)", System.nanoTime() - t0, n);
            check(delivered == n, "every pair-MAC datagram delivered");

            TruncatedMac mac = new TruncatedMac(new byte[32]);
            byte[] datagram = macd[0].clone();
            int length = datagram.length - TruncatedMac.BYTES;
            mac.sign(datagram, length);
            t0 = System.nanoTime();
            int ok = 0;
            for (int i = 0; i < n; i++) {
                ok += mac.verify(datagram, length) ? 1 : 0;
            }
            report("HMAC-SHA256/128 verify alone", System.nanoTime() - t0, n);
            check(ok == n, "MAC verifies");

            byte[][] team16 = new byte[n][];
            for (int i = 0; i < n; i++) {
                team16[i] = a.wrapTeam(heartbeat);
            }
            t0 = System.nanoTime();
            for (int i = 0; i < n; i++) {
                b.unwrap(team16[i]);
            }
            report("team-MAC unwrap", System.nanoTime() - t0, n);

            int m = 2_000;
            byte[] message = a.wrapSigned(heartbeat);
            VerificationKey key = a.identity.key().verificationKey();
            byte[] signature = a.identity.key().sign(message);
            t0 = System.nanoTime();
            for (int i = 0; i < m; i++) {
                ok += key.verify(message, signature) ? 1 : 0;
            }
            report("Ed25519 verify (one signature)", System.nanoTime() - t0, m);
            t0 = System.nanoTime();
            for (int i = 0; i < m; i++) {
                a.identity.key().sign(message);
            }
            report("Ed25519 sign", System.nanoTime() - t0, m);

            byte[][] signed = new byte[m][];
            for (int i = 0; i < m; i++) {
                signed[i] = a.wrapSigned(heartbeat);
            }
            t0 = System.nanoTime();
            for (int i = 0; i < m; i++) {
                b.unwrap(signed[i]);
            }
            report("signed unwrap, credential already verified (one Ed25519 verify)", System.nanoTime() - t0, m);

            int h = 300;
            Identity other = team.identity("uav-99");
            t0 = System.nanoTime();
            for (int i = 0; i < h; i++) {
                team.clock.advance(1);   // a restart within the same millisecond would count where the last one did
                SecureEndpoint fresh = SecureEndpoint.builder(other, team.trust, team.clock).random(team.random).build();
                Team.shakeHands(fresh, b);
            }
            report("handshake, both sides (2 X25519 keys, 2 agreements, 2 signs, 4 verifies)", System.nanoTime() - t0, h);
            System.out.println();
        }
    }

    private static void report(String what, long nanos, int n) {
        System.out.println(String.format(Locale.ROOT, "  %-78s %10.2f µs", what, nanos / 1_000.0 / n));
    }

    private static void check(boolean condition, String what) {
        if (!condition) {
            throw new IllegalStateException("probe broken: not " + what);
        }
    }
}
