package net.smc.core.capability;

import java.util.List;

/** An event a task raises: its name and its attributes (name and Java simple type name), in order. */
public record EventDescription(String name, List<Attribute> attributes) {
    public EventDescription {
        attributes = List.copyOf(attributes);
    }

    /** One attribute of an event, e.g. {@code x} of type {@code double}. */
    public record Attribute(String name, String type) {
    }
}
