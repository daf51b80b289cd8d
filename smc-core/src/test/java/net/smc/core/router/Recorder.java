package net.smc.core.router;

import java.util.ArrayList;
import java.util.List;
import net.smc.core.message.Envelope;

/** A subscriber that remembers what it received. */
final class Recorder implements Subscriber {
    final String name;
    final List<Envelope> received = new ArrayList<>();

    Recorder(String name) {
        this.name = name;
    }

    @Override
    public void receive(Envelope envelope) {
        received.add(envelope);
    }

    @Override
    public String toString() {
        return name;
    }
}
