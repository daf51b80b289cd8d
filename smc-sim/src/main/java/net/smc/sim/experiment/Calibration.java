package net.smc.sim.experiment;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.SecureRandom;
import java.util.List;

import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

import org.bouncycastle.math.ec.rfc7748.X25519;

import net.smc.core.message.Envelope;
import net.smc.core.message.Heartbeat;
import net.smc.core.message.MessageDecoder;
import net.smc.core.message.MessageEncoder;
import net.smc.core.message.PolicyReply;
import net.smc.core.message.RoleEvent;
import net.smc.core.security.SigningKey;
import net.smc.core.security.VerificationKey;
import net.smc.policy.PolicyEngine;
import net.smc.policy.RunResult;

/**
 * Measures, on this machine, what the operations {@link CpuCharge} charges cost this engine (the
 * project's Ed25519 keys and codec, the JDK's HMAC-SHA256 and Bouncy Castle's X25519 as the security
 * layer uses them, the PonderTalk engine loading a generated role-mission into a booted engine and
 * offering an event to policies):
 * the calibration step of the set-up time experiment. The codec's cost per byte is measured on a
 * message it writes as it is (a role event with a long string); deflating and inflating a policy
 * text, on the generated manager's role-mission as the codec sends it, less the codec's own cost of
 * the datagram, per byte of text. Each operation is warmed up for half a second
 * (so the JIT has compiled it), then timed in several batches of at least 50 ms, and the fastest
 * batch is kept: on a machine shared with other work the fastest batch is the one least slowed by
 * it, closest to what the operation costs a CPU of its own. This is the one
 * part of the experiment that reads the wall clock; the costs it returns are then applied
 * deterministically ({@link CpuCosts#save}, {@link CpuCosts#load}).
 */
public final class Calibration {
    private static final int BATCHES = 5;
    private static final long WARM_UP_NANOS = 500_000_000L;
    private static final long BATCH_NANOS = 50_000_000L;

    private Calibration() {
    }

    /**
     * Measures every cost.
     *
     * @param bootEvents the project's {@code policies/boot/events.p2}
     * @param mission    a generated mission whose first manager's role-mission is the policy text loaded
     */
    public static CpuCosts measure(Path bootEvents, GeneratedMission mission) throws Exception {
        SigningKey key = SigningKey.generate(new SecureRandom(new byte[] {1}));
        VerificationKey pub = key.verificationKey();
        byte[] msg = new byte[200];
        double sign = time(20, () -> key.sign(msg));
        // Distinct signed messages, more than the security layer's memo of valid signatures holds,
        // so that every verification is the arithmetic and not a hit in the memo.
        int distinct = 512;
        byte[][] msgs = new byte[distinct][];
        byte[][] sigs = new byte[distinct][];
        for (int i = 0; i < distinct; i++) {
            msgs[i] = new byte[200];
            msgs[i][0] = (byte) i;
            msgs[i][1] = (byte) (i >>> 8);
            sigs[i] = key.sign(msgs[i]);
        }
        int[] next = {0};
        double verify = time(20, () -> {
            int i = next[0]++ % distinct;
            if (!pub.verify(msgs[i], sigs[i])) {
                throw new IllegalStateException("calibration: a valid signature did not verify");
            }
        });

        // One side of a first contact: a fresh ephemeral key pair and the agreement with the peer's
        // public value (net.smc.core.security's handshake, by the same Bouncy Castle RFC 7748 code).
        byte[] peerScalar = new byte[X25519.SCALAR_SIZE];
        new SecureRandom(new byte[] {2}).nextBytes(peerScalar);
        byte[] peerPublic = new byte[X25519.POINT_SIZE];
        X25519.generatePublicKey(peerScalar, 0, peerPublic, 0);
        SecureRandom random = new SecureRandom(new byte[] {3});
        double agree = time(20, () -> {
            byte[] scalar = new byte[X25519.SCALAR_SIZE];
            random.nextBytes(scalar);
            byte[] mine = new byte[X25519.POINT_SIZE];
            X25519.generatePublicKey(scalar, 0, mine, 0);
            byte[] secret = new byte[X25519.POINT_SIZE];
            if (!X25519.calculateAgreement(scalar, 0, peerPublic, 0, secret, 0)) {
                throw new IllegalStateException("X25519 agreement failed");
            }
        });

        Mac mac = Mac.getInstance("HmacSHA256");
        mac.init(new SecretKeySpec(new byte[32], "HmacSHA256"));
        byte[] small = new byte[64];
        byte[] large = new byte[1_400];
        double macSmall = time(100, () -> mac.doFinal(small));
        double macLarge = time(100, () -> mac.doFinal(large));
        double macPerByte = Math.max(0, (macLarge - macSmall) / (large.length - small.length));
        double macFixed = Math.max(0, macSmall - macPerByte * small.length);

        MessageEncoder encoder = new MessageEncoder();
        MessageDecoder decoder = new MessageDecoder(() -> 0L);
        Envelope hb = new Envelope("b0l1n0", 1, new Heartbeat("b0l1", 1, 0));
        Envelope event = new Envelope("b0l1n0", 2, new RoleEvent("b0l1", "report", List.of("x".repeat(1_200))));
        int hbBytes = encoder.datagrams(hb).get(0).length;
        int eventBytes = encoder.datagrams(event).get(0).length;
        double codecSmall = time(100, () -> decoder.decode(encoder.datagrams(hb).get(0))) / 2;
        double codecLarge = time(100, () -> decoder.decode(encoder.datagrams(event).get(0))) / 2;
        double codecPerByte = Math.max(0, (codecLarge - codecSmall) / (eventBytes - hbBytes));
        double codecFixed = Math.max(0, codecSmall - codecPerByte * hbBytes);

        // A manager's role-mission as its manager sends it: deflated by the encoder, inflated by the
        // decoder. Each side's time less that of a heartbeat and the codec's per-byte cost of the
        // longer datagram is the compression's, per byte of text.
        RoleType manager = mission.roles().get(0);
        String text = Files.readString(mission.repository().resolve("roles/" + manager.name() + "/mission.p2"));
        int textBytes = text.getBytes(StandardCharsets.UTF_8).length;
        Envelope policy = new Envelope("b0l1n0", 3, new PolicyReply(1, "policy:/roles/b0l1/mission", 1, text));
        byte[] hbDatagram = encoder.datagrams(hb).get(0);
        List<byte[]> policyDatagrams = encoder.datagrams(policy);
        if (policyDatagrams.size() != 1) {
            throw new IllegalStateException("calibration: a manager's role-mission of " + textBytes
                    + " bytes took " + policyDatagrams.size() + " datagrams; one was expected");
        }
        byte[] policyDatagram = policyDatagrams.get(0);
        double longer = codecPerByte * (policyDatagram.length - hbBytes);
        double encodeSmall = time(100, () -> encoder.datagrams(hb));
        double encodePolicy = time(100, () -> encoder.datagrams(policy));
        double decodeSmall = time(100, () -> decoder.decode(hbDatagram));
        double decodePolicy = time(100, () -> decoder.decode(policyDatagram));
        double deflatePerByte = Math.max(0, (encodePolicy - encodeSmall - longer) / textBytes);
        double inflatePerByte = Math.max(0, (decodePolicy - decodeSmall - longer) / textBytes);

        String boot = Files.readString(bootEvents);
        // What a vehicle does when it takes a role, per byte of the role's policy text.
        RoleLoadWork load = new RoleLoadWork(bootEvents, mission);
        double loadPerByte = time(20, load::loadAndWithdraw) / load.bytes();

        int policies = 20;
        PolicyEngine cell = PolicyEngine.builder().build();
        check(cell.run("boot", boot));
        StringBuilder conditions = new StringBuilder();
        for (int i = 0; i < policies; i++) {
            conditions.append("p := root/factory/ecapolicy create.\n")
                    .append("p event: /event/newUAV; condition: [:uav | uav == \"nobody").append(i)
                    .append("\"]; action: [:uav | root print: uav]. p active: true.\n");
        }
        check(cell.run("conditions", conditions.toString()));
        double raise = time(50, () -> cell.raise("root/event/newUAV", "newUAV", "b0l1n0", "summary", "credential"));
        double condition = raise / policies;

        return new CpuCosts(sign, verify, agree, macFixed, macPerByte, codecFixed, codecPerByte, loadPerByte, condition,
                deflatePerByte, inflatePerByte);
    }

    private static void check(RunResult r) {
        if (!r.ok()) {
            throw new IllegalStateException("calibration policy failed: " + r.diagnostics());
        }
    }

    /** The fastest batch's time of one call, in ns ({@code minCalls}: at least this many calls per batch). */
    private static double time(int minCalls, Work work) throws Exception {
        long warm = System.nanoTime();
        while (System.nanoTime() - warm < WARM_UP_NANOS) {
            work.run();
        }
        double best = Double.MAX_VALUE;
        for (int b = 0; b < BATCHES; b++) {
            long t0 = System.nanoTime();
            long calls = 0;
            long elapsed;
            do {
                work.run();
                calls++;
                elapsed = System.nanoTime() - t0;
            } while (calls < minCalls || elapsed < BATCH_NANOS);
            best = Math.min(best, elapsed / (double) calls);
        }
        return best;
    }

    @FunctionalInterface
    private interface Work {
        void run() throws GeneralSecurityException, Exception;
    }
}
