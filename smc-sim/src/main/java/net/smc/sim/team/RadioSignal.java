package net.smc.sim.team;

import java.util.List;
import java.util.Objects;

import net.smc.core.cell.Cell;
import net.smc.policy.runtime.Domain;
import net.smc.policy.runtime.EventTemplate;
import net.smc.policy.runtime.Managed;
import net.smc.policy.runtime.Op;
import net.smc.policy.runtime.PArray;
import net.smc.policy.runtime.PonderError;

/**
 * CROSS-VEHICLE EVENTS, the one place of the rescue that passes an event from one vehicle's cell
 * to others': {@code root/signal send: "distress" with: #(x y condition)} sends a radio signal that
 * every other live cell within radio reach of the sender (a fresh draw of the world's radio per
 * receiver) receives {@link #DELAY_MILLIS} later as the event {@code root/event/<name>}, if it
 * has that template. It is how the soldier's wearable computer calls for help (a beacon heard by
 * whoever is near). When roles publish events to roles on other vehicles (authenticated, over the
 * team's messages), the wearable's policy switches to that mechanism and this object goes.
 */
@Managed("RadioSignal")
public final class RadioSignal {
    /** Time from sending to hearing, ms. */
    static final long DELAY_MILLIS = 5;
    /** The name under root. */
    static final String NAME = "signal";

    private final TeamSimulation team;
    private final String sender;
    private long sent;

    RadioSignal(TeamSimulation team, String sender) {
        this.team = Objects.requireNonNull(team, "team");
        this.sender = Objects.requireNonNull(sender, "sender");
    }

    void install(net.smc.policy.Cell engine) {
        if (engine.root().get(NAME) == null) {
            engine.root().put(NAME, net.smc.policy.Cell.manage(this));
        }
    }

    /** Sends the signal {@code event} with {@code values} (the event's attributes, in order). */
    @Op("send:with:")
    public long send(String event, PArray values) {
        if (event == null || !event.matches("[A-Za-z][A-Za-z0-9_]*")) {
            throw new PonderError("RadioSignal send:with: the event name '" + event + "' must be letters, digits and _");
        }
        List<Object> copy = List.copyOf(values.items());
        var radio = team.world().world().radio();
        for (String vehicle : team.vehicles().stream().map(SimVehicle::id).toList()) {
            if (vehicle.equals(sender) || !team.isLive(vehicle)
                    || !radio.reachable(team.address(sender), team.address(vehicle))) {
                continue;
            }
            team.scheduler().schedule(DELAY_MILLIS, () -> hear(vehicle, event, copy));
        }
        return ++sent;
    }

    private void hear(String vehicle, String event, List<Object> values) {
        Cell cell = team.cell(vehicle);
        if (cell == null || !(cell.engine().root().get("event") instanceof Domain events)
                || !(events.get(event) instanceof EventTemplate)) {
            return;
        }
        cell.engine().raise("root/event/" + event, values.toArray());
    }
}
