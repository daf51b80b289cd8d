package net.smc.core.mission;

import java.util.List;

/**
 * What a role of a mission class offers to and needs from the roles of other vehicles (the
 * paper's section II-B.2.A), from the behaviour's {@code <interface>}: the events its tasks raise
 * that it publishes, the events of other roles it subscribes to (they trigger its policies), the
 * operations of its tasks it offers, and the operations of other roles it uses. Cells route a
 * published event to the vehicles holding a role that subscribes to it.
 */
public record RoleInterface(List<String> publishes, List<String> subscribes, List<Offer> offers, List<Use> uses) {

    /** Nothing published, subscribed, offered or used. */
    public static final RoleInterface NONE = new RoleInterface(List.of(), List.of(), List.of(), List.of());

    public RoleInterface {
        publishes = List.copyOf(publishes);
        subscribes = List.copyOf(subscribes);
        offers = List.copyOf(offers);
        uses = List.copyOf(uses);
    }

    /** An operation of one of the role's tasks, offered to other roles: {@code <offers task="Aggregator">report:x:y:</offers>}. */
    public record Offer(String task, String selector) {
    }

    /** An operation the role invokes on another role: {@code <uses role="aggregator">report:x:y:</uses>}. */
    public record Use(String role, String selector) {
    }
}
