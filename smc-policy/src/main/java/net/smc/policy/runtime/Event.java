package net.smc.policy.runtime;

/** One raised event: its template and its attribute values, in the template's name order. */
record Event(EventTemplate template, Object[] values) {

    /** The value of an attribute, or {@code null} if the template has no such attribute. */
    Object get(String name) {
        int i = template.indexOf(name);
        return i < 0 ? null : values[i];
    }

    /** The event as one hash, attribute name to value. */
    PHash asHash() {
        PHash h = new PHash();
        for (int i = 0; i < values.length; i++) {
            h.put(template.attributeNames().get(i), values[i]);
        }
        return h;
    }
}
