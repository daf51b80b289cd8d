package net.smc.policy.api;

import java.util.Map;

/** A domain: named entries, each any value; adding a handle makes the domain one of its parents. */
public interface DomainHandle extends Handle {

    /** The entry with this name, or {@code null}. */
    Object get(String name);

    /**
     * Adds or replaces an entry, as {@code at:put:} does.
     *
     * @throws PonderError when the name is not letters, digits and _
     */
    void put(String name, Object value);

    /** Removes an entry and answers what it held (nil when there was none). */
    Object remove(String name);

    /** Removes every entry. */
    DomainHandle removeAll();

    /** Whether some entry holds {@code value}. */
    boolean hasObject(Object value);

    /** The entries, in insertion order (read-only). */
    Map<String, Object> entries();
}
