package net.smc.core.security;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The signatures found valid lately, each with the exact bytes it was checked over: so that the
 * same signed datagram arriving at several cells of one process (a broadcast in a simulated team,
 * where every receiver runs in the same JVM) costs one Ed25519 verification, not one per receiver.
 *
 * <p>It is a memo, not a shortcut: an entry matches only when the public key, every signed byte and
 * every signature byte are equal to those of a verification that succeeded (compared in full, not by
 * a hash), and Ed25519 verification is a function of those three, so a hit gives the answer the
 * arithmetic would give. Failures are not remembered (they are cheap to repeat and a forger's bytes
 * should not evict honest ones). What happens after the signature (freshness, replay window,
 * credential) is checked by each receiver as before.
 *
 * <p>Bounded: the {@value #CAPACITY} most recently used entries; thread-safe (the cells of a live
 * team run on threads of their own).
 */
final class VerifiedSignatures {
    /** Entries kept: enough for every signed datagram of a crowded moment, each a few hundred bytes. */
    static final int CAPACITY = 256;

    /** The process-wide memo. */
    static final VerifiedSignatures SHARED = new VerifiedSignatures(CAPACITY);

    private final Map<Signed, Signed> entries;
    private long hits;
    private long misses;

    VerifiedSignatures(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("capacity " + capacity + " must be 1 or more");
        }
        this.entries = new LinkedHashMap<>(capacity * 2, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<Signed, Signed> eldest) {
                return size() > capacity;
            }
        };
    }

    /**
     * Whether {@code key} verified the 64 bytes at {@code signature[sigOffset]} as its signature of
     * {@code data[offset, offset + length)} lately; the caller has checked the ranges.
     */
    synchronized boolean contains(VerificationKey key, byte[] data, int offset, int length, byte[] signature, int sigOffset) {
        boolean hit = entries.get(new Signed(key, data, offset, length, signature, sigOffset)) != null;
        if (hit) {
            hits++;
        } else {
            misses++;
        }
        return hit;
    }

    /** Remembers a verification that succeeded (copies the bytes). */
    synchronized void add(VerificationKey key, byte[] data, int offset, int length, byte[] signature, int sigOffset) {
        Signed s = new Signed(key, Arrays.copyOfRange(data, offset, offset + length), 0, length,
                Arrays.copyOfRange(signature, sigOffset, sigOffset + SigningKey.SIGNATURE_BYTES), 0);
        entries.put(s, s);
    }

    synchronized long hits() {
        return hits;
    }

    synchronized long misses() {
        return misses;
    }

    synchronized int size() {
        return entries.size();
    }

    /** A key, a range of signed bytes and a signature, equal only when all three are equal byte for byte. */
    private static final class Signed {
        private final VerificationKey key;
        private final byte[] data;
        private final int offset;
        private final int length;
        private final byte[] signature;
        private final int sigOffset;
        private final int hash;

        Signed(VerificationKey key, byte[] data, int offset, int length, byte[] signature, int sigOffset) {
            this.key = key;
            this.data = data;
            this.offset = offset;
            this.length = length;
            this.signature = signature;
            this.sigOffset = sigOffset;
            int h = key.hashCode();
            for (int i = sigOffset; i < sigOffset + SigningKey.SIGNATURE_BYTES; i++) {
                h = 31 * h + signature[i];
            }
            this.hash = 31 * h + length;
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Signed s && length == s.length && hash == s.hash
                    && Arrays.equals(signature, sigOffset, sigOffset + SigningKey.SIGNATURE_BYTES,
                            s.signature, s.sigOffset, s.sigOffset + SigningKey.SIGNATURE_BYTES)
                    && Arrays.equals(data, offset, offset + length, s.data, s.offset, s.offset + length)
                    && key.equals(s.key);
        }

        @Override
        public int hashCode() {
            return hash;
        }
    }
}
