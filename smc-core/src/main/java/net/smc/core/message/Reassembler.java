package net.smc.core.message;

import java.util.Arrays;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Joins the fragments of messages, keyed by {@code (sender, id)}, in any order, and makes sure
 * that a peer which never sends the rest cannot make it hold anything for long:
 * <ul>
 *   <li>a reassembly expires {@link ReassemblySettings#expiryMillis()} after its first fragment,
 *       measured on the injected clock (it must not run backwards);</li>
 *   <li>the bytes held over all reassemblies stay within {@link ReassemblySettings#maxBufferedBytes()},
 *       and the reassemblies within {@link ReassemblySettings#maxReassemblies()}: to make room the
 *       oldest reassembly is evicted.</li>
 * </ul>
 * Each chunk is copied as it arrives, so a fragment makes it allocate no more than the fragment's
 * own bytes; the whole payload is allocated once, when the last chunk arrives.
 *
 * <p>A message whose fragments all arrive twice is reassembled twice: suppressing duplicate
 * messages by {@code (sender, id)} is the receiver's job, for single datagrams as much as for these.
 */
final class Reassembler {
    /** The outcome of one accepted fragment; {@code payload} is null until the message is complete. */
    record Progress(int received, byte[] payload) {
    }

    private record Key(String sender, long id) {
    }

    private static final class Partial {
        final FragmentHeader first;
        final long startedAt;
        final byte[][] chunks;
        int received;
        int bytes;

        Partial(FragmentHeader first, long startedAt) {
            this.first = first;
            this.startedAt = startedAt;
            this.chunks = new byte[first.count()][];
        }
    }

    private final ReassemblySettings settings;
    /** In order of first fragment, oldest first: the order of expiry and of eviction. */
    private final LinkedHashMap<Key, Partial> partials = new LinkedHashMap<>();
    private long bufferedBytes;
    private long started;
    private long completed;
    private long expired;
    private long evicted;

    Reassembler(ReassemblySettings settings) {
        this.settings = settings;
    }

    /**
     * Stores one fragment whose frame {@link FragmentHeader#read} has checked; its chunk is
     * {@code chunk[off, off + f's chunk length)}.
     *
     * @throws DecodeException a duplicate, or a frame that disagrees with its siblings
     */
    Progress accept(String sender, long id, FragmentHeader f, byte[] chunk, int off, long now) throws DecodeException {
        expire(now);
        Key key = new Key(sender, id);
        Partial p = partials.get(key);
        if (p == null) {
            while (partials.size() >= settings.maxReassemblies()) {
                evictOldest(null);
            }
            p = new Partial(f, now);
            partials.put(key, p);
            started++;
        } else if (!p.first.type().equals(f.type()) || p.first.count() != f.count() || p.first.total() != f.total()) {
            throw new DecodeException(RejectReason.BAD_FRAGMENT, "fragment " + f.index() + " says " + f.count()
                    + " fragments of a " + f.total() + "-byte " + f.type() + "; earlier fragments said "
                    + p.first.count() + " of a " + p.first.total() + "-byte " + p.first.type());
        }
        if (p.chunks[f.index()] != null) {
            throw new DecodeException(RejectReason.DUPLICATE_FRAGMENT, "fragment " + f.index() + " of "
                    + f.count() + " is already held");
        }
        int len = Fragmenter.chunkLength(f.index(), f.count(), f.total());
        while (bufferedBytes + len > settings.maxBufferedBytes()) {
            evictOldest(p);
        }
        p.chunks[f.index()] = Arrays.copyOfRange(chunk, off, off + len);
        p.received++;
        p.bytes += len;
        bufferedBytes += len;
        if (p.received < f.count()) {
            return new Progress(p.received, null);
        }
        partials.remove(key);
        bufferedBytes -= p.bytes;
        completed++;
        byte[] payload = new byte[f.total()];
        for (int i = 0; i < f.count(); i++) {
            System.arraycopy(p.chunks[i], 0, payload, Fragmenter.offset(i, f.count(), f.total()), p.chunks[i].length);
        }
        return new Progress(p.received, payload);
    }

    /** Drops every reassembly whose time is up at {@code now}. */
    void expire(long now) {
        Iterator<Partial> it = partials.values().iterator();
        while (it.hasNext()) {
            Partial p = it.next();
            if (now - p.startedAt < settings.expiryMillis()) {
                return;  // the rest started later
            }
            it.remove();
            bufferedBytes -= p.bytes;
            expired++;
        }
    }

    /** Evicts the oldest reassembly other than {@code keep}. */
    private void evictOldest(Partial keep) {
        Iterator<Map.Entry<Key, Partial>> it = partials.entrySet().iterator();
        while (it.hasNext()) {
            Partial p = it.next().getValue();
            if (p != keep) {
                it.remove();
                bufferedBytes -= p.bytes;
                evicted++;
                return;
            }
        }
        throw new IllegalStateException("nothing to evict: settings admit no message");
    }

    int inProgress() {
        return partials.size();
    }

    long bufferedBytes() {
        return bufferedBytes;
    }

    long started() {
        return started;
    }

    long completed() {
        return completed;
    }

    long expired() {
        return expired;
    }

    long evicted() {
        return evicted;
    }
}
