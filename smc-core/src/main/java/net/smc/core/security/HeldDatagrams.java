package net.smc.core.security;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;

import net.smc.core.transport.Address;

/**
 * The datagrams an {@link AuthenticatingTransport} holds unchecked for its receiver to read first
 * ({@link AuthenticatingTransport#holdUnverified}): the newest per source address, at most
 * {@link #MAX_HELD} in all, the oldest going first when a new source comes. Shared by the real
 * transport and the simulated one, which differ only in how they find a datagram's payload. One
 * cell thread.
 */
final class HeldDatagrams {
    /** At most this many datagrams are held; the oldest goes first. */
    static final int MAX_HELD = 256;

    private UnverifiedTest readable = UnverifiedTest.NONE;
    private UnverifiedReceiver receiver;
    /** The datagrams held, the newest per source address, oldest first. */
    private final Map<Address, byte[]> held = new LinkedHashMap<>();
    private long count;

    /** Starts holding the datagrams whose payload {@code readable} accepts, handing them to {@code receiver}. */
    void set(UnverifiedTest readable, UnverifiedReceiver receiver) {
        this.readable = Objects.requireNonNull(readable, "readable");
        this.receiver = Objects.requireNonNull(receiver, "receiver");
    }

    /** Whether a datagram whose payload is {@code length} bytes at {@code offset} of {@code data} is held. */
    boolean accepts(byte[] data, int offset, int length) {
        return receiver != null && readable.test(data, offset, length);
    }

    /** Holds {@code datagram} from {@code from} in place of any held before from there, and hands {@code payload} to the receiver. */
    void hold(Address from, byte[] datagram, byte[] payload) {
        held.remove(from);
        if (held.size() >= MAX_HELD) {
            held.remove(held.keySet().iterator().next());
        }
        held.put(from, datagram);
        count++;
        receiver.onUnverified(from, payload);
    }

    /**
     * The datagram held from {@code from}, no longer held, handed to {@code check} (the transport's
     * every check, then its delivery); whether one was held.
     */
    boolean check(Address from, Consumer<byte[]> check) {
        byte[] data = take(from);
        if (data == null) {
            return false;
        }
        check.accept(data);
        return true;
    }

    /** The datagram held from {@code from}, no longer held; null when none is. */
    byte[] take(Address from) {
        return held.remove(Objects.requireNonNull(from, "from"));
    }

    /** Datagrams held so far. */
    long count() {
        return count;
    }
}
