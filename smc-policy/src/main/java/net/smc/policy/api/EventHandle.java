package net.smc.policy.api;

import java.util.List;

/** An event template: events of it carry one value per attribute; raise them with {@code PolicyEngine.raise}. */
public interface EventHandle extends Handle {

    /** The names of the attributes, in order. */
    List<String> attributeNames();
}
