package net.smc.core.security;

import java.security.GeneralSecurityException;
import java.security.KeyPair;
import java.security.KeyPairGenerator;
import java.security.SecureRandom;
import java.security.Signature;
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
    }

    @Benchmark
    public byte[] sign() {
        return key.sign(message);
    }

    @Benchmark
    public boolean verify() {
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
