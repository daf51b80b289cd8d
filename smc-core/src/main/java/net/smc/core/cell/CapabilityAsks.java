package net.smc.core.cell;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.BiConsumer;

/**
 * How many vehicles a manager asks for their full descriptions at a time. A manager asks no more
 * vehicles for a role than it could seat and {@link #ASK_MARGIN} (for those that turn out taken or
 * unable): in a large team every free vehicle in reach answers every manager's discovery, and asking
 * each of them costs both a request and a full description for a seat most will not get. The
 * others wait in {@link TeamState#deferredAsks} and are asked as requests out end unseated.
 */
final class CapabilityAsks {
    /** How many capability requests for a role may be out beyond its open seats. */
    static final int ASK_MARGIN = 2;

    private final TeamContext ctx;
    private final TeamState st;

    CapabilityAsks(TeamContext ctx, TeamState st) {
        this.ctx = ctx;
        this.st = st;
    }

    /** This cell's open seats of {@code role}. */
    long openSeats(String role) {
        return st.owned.keySet().stream().filter(s -> s.role().equals(role) && st.open(s)).count();
    }

    /** Whether as many vehicles are asked for {@code role} as its open seats and the margin allow. */
    boolean full(String role) {
        return asksOut(role) >= openSeats(role) + ASK_MARGIN;
    }

    /** {@code uav} waits its turn to be asked for {@code role}. */
    void defer(String uav, String role) {
        st.deferredAsks.computeIfAbsent(uav, v -> new LinkedHashSet<>()).add(role);
    }

    /**
     * Asks deferred vehicles, oldest first, as far as the margin allows (by {@code ask}); forgets
     * those that are now children, already asked, or not heard within the failure timeout, and roles
     * with no open seat.
     */
    void askDeferred(BiConsumer<String, String> ask) {
        long now = ctx.clock().nowMillis();
        for (String uav : List.copyOf(st.deferredAsks.keySet())) {
            TeamState.Heard heard = st.heard.get(uav);
            if (heard == null || now - heard.atMillis() > ctx.timing().failureTimeoutMillis()
                    || st.children.containsKey(uav) || st.capabilityRequests.containsKey(uav)) {
                st.deferredAsks.remove(uav);
                continue;
            }
            Set<String> roles = st.deferredAsks.get(uav);
            for (String role : List.copyOf(roles)) {
                long open = openSeats(role);
                if (open == 0) {
                    roles.remove(role);
                } else if (asksOut(role) < open + ASK_MARGIN) {
                    roles.remove(role);
                    ask.accept(uav, role);
                }
            }
            if (roles.isEmpty()) {
                st.deferredAsks.remove(uav);
            }
        }
    }

    private long asksOut(String role) {
        return st.capabilityRequests.values().stream().filter(p -> p.roles.contains(role)).count();
    }
}
