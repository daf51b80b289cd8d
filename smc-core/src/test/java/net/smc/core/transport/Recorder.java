package net.smc.core.transport;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/** A receiver that records what arrives, as "from text" lines, and signals each arrival. */
public final class Recorder implements Receiver {
    private final Signal signal;
    private final List<String> received = new ArrayList<>();

    public Recorder(Signal signal) {
        this.signal = signal;
    }

    @Override
    public void onDatagram(Address from, byte[] data) {
        synchronized (this) {
            received.add(from + " " + new String(data, StandardCharsets.UTF_8));
        }
        signal.changed();
    }

    public synchronized List<String> received() {
        return new ArrayList<>(received);
    }

    public synchronized int count() {
        return received.size();
    }

    public synchronized boolean has(String line) {
        return received.contains(line);
    }
}
