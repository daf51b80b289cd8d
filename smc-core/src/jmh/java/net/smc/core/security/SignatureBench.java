package net.smc.core.security;

import java.security.GeneralSecurityException;
import java.security.KeyPair;
import java.security.KeyPairGenerator;
import java.security.SecureRandom;
import java.security.Signature;
import java.util.Random;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * One Ed25519 signature and one verification of a 200-byte message (a discovery datagram's size):
 * {@link SigningKey} and {@link VerificationKey} against the JDK 17's own provider, the baseline,
 * in the same run. Signed datagrams (discovery, first contact, credentials) cost a cell this much.
 *
 * <p>{@link VerificationKey#verify} remembers the signatures it found valid lately
 * ({@link VerifiedSignatures}, so that one broadcast costs a simulated team one verification), so
 * {@code verify} goes round more signed messages than the memo holds, each seen again only after
 * the memo has dropped it: every call is a verification, with the memo's look-up and entry as a cell
 * pays them for a new signature. {@code verifyRemembered} checks one signature over and over: the
 * memo's hit, what every receiver after the first pays for the same broadcast.
 */
@State(Scope.Thread)
@Fork(1)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class SignatureBench {
    private final byte[] message = new byte[200];
    private SigningKey key;
    private byte[] signature;
    private KeyPair jdkPair;
    private byte[] jdkSignature;
    /** More signed messages than the memo of valid signatures holds, and their signatures. */
    private final byte[][] messages = new byte[2 * VerifiedSignatures.CAPACITY + 1][];
    private final byte[][] signatures = new byte[messages.length][];
    private int next;

    @Setup
    public void setUp() throws GeneralSecurityException {
        new SecureRandom(new byte[] {4}).nextBytes(message);
        key = SigningKey.generate(new SecureRandom(new byte[] {1}));
        signature = key.sign(message);
        jdkPair = KeyPairGenerator.getInstance("Ed25519").generateKeyPair();
        jdkSignature = jdkSign();
        if (!key.verificationKey().verify(message, signature) || !jdkVerify()) {
            throw new IllegalStateException("a signature made in set-up does not verify");
        }
        Random random = new Random(5);
        for (int i = 0; i < messages.length; i++) {
            messages[i] = new byte[message.length];
            random.nextBytes(messages[i]);
            signatures[i] = key.sign(messages[i]);
        }
    }

    @Benchmark
    public byte[] sign() {
        return key.sign(message);
    }

    /** A signature the memo does not hold: an Ed25519 verification. */
    @Benchmark
    public boolean verify() {
        int i = next;
        next = i + 1 == messages.length ? 0 : i + 1;
        return key.verificationKey().verify(messages[i], signatures[i]);
    }

    /** The same signature again: the memo's answer. */
    @Benchmark
    public boolean verifyRemembered() {
        return key.verificationKey().verify(message, signature);
    }

    @Benchmark
    public byte[] jdkSign() throws GeneralSecurityException {
        Signature signer = Signature.getInstance("Ed25519");
        signer.initSign(jdkPair.getPrivate());
        signer.update(message);
        return signer.sign();
    }

    @Benchmark
    public boolean jdkVerify() throws GeneralSecurityException {
        Signature verifier = Signature.getInstance("Ed25519");
        verifier.initVerify(jdkPair.getPublic());
        verifier.update(message);
        return verifier.verify(jdkSignature);
    }
}
