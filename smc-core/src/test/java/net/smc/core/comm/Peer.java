package net.smc.core.comm;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;

import net.smc.core.message.Envelope;
import net.smc.core.message.Message;
import net.smc.core.router.MessageRouter;
import net.smc.core.transport.Address;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Signal;

/**
 * A cell under test: a communication manager whose router records every application message, and
 * the outcome of every critical message it sent. Thread-safe to read from a test thread (UDP);
 * {@link #send} must run on the cell's thread.
 */
final class Peer {
    /** The outcome of one critical message: when it was sent, and "delivered" or the failure reason, and when. */
    static final class Outcome {
        final long sentMillis;
        volatile String result;
        volatile long settledMillis;
        final AtomicInteger calls = new AtomicInteger();

        Outcome(long sentMillis) {
            this.sentMillis = sentMillis;
        }
    }

    final CommunicationManager manager;
    final MessageRouter router = new MessageRouter();
    private final Clock clock;
    private final Signal signal;
    /** Application deliveries by "sender#id". */
    final Map<String, AtomicInteger> received = new ConcurrentHashMap<>();
    final Map<Long, Outcome> outcomes = new ConcurrentHashMap<>();
    final AtomicInteger settled = new AtomicInteger();
    final AtomicInteger receivedTotal = new AtomicInteger();

    Peer(CommunicationManager.Builder builder, Clock clock, Signal signal) {
        this.clock = clock;
        this.signal = signal;
        for (var type : net.smc.core.message.MessageType.values()) {
            router.register(this::record, type);
        }
        this.manager = builder.router(router).build();
        manager.start();
    }

    private void record(Envelope e) {
        received.computeIfAbsent(e.sender() + "#" + e.id(), k -> new AtomicInteger()).incrementAndGet();
        receivedTotal.incrementAndGet();
        signal.changed();
    }

    Address address() {
        return manager.localAddress();
    }

    String id() {
        return manager.vehicleId();
    }

    /** Sends reliably, recording the outcome. Call on the cell's thread. */
    long send(Peer to, Message m) {
        Outcome o = new Outcome(clock.nowMillis());
        long id = manager.send(to.address(), m, new DeliveryListener() {
            @Override
            public void delivered(long id) {
                settle(id, "delivered");
            }

            @Override
            public void failed(long id, FailureReason reason) {
                settle(id, reason.name());
            }
        });
        outcomes.put(id, o);
        return id;
    }

    private void settle(long id, String result) {
        Outcome o = outcomes.get(id);
        o.calls.incrementAndGet();
        o.result = result;
        o.settledMillis = clock.nowMillis();
        settled.incrementAndGet();
        signal.changed();
    }

    /** How often the application of this peer got message {@code id} from {@code from}. */
    int times(Peer from, long id) {
        AtomicInteger n = received.get(from.id() + "#" + id);
        return n == null ? 0 : n.get();
    }
}
