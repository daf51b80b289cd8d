package net.smc.sim.team;

import java.util.Objects;

import net.smc.core.cell.Cell;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.api.PonderError;

/**
 * CROSS-VEHICLE EVENTS, the one place of the rescue that passes an event from one vehicle's cell
 * to others': {@code root/signal distress: x y: y condition: c} sends a distress signal that
 * every other live cell within radio reach of the sender (a fresh draw of the world's radio per
 * receiver) receives {@link #DELAY_MILLIS} later as the event {@code root/event/distress}
 * ({@code policy:/boot/events} makes its template in every cell). It is how the soldier's wearable computer calls for help (a beacon heard by
 * whoever is near). When roles publish events to roles on other vehicles (authenticated, over the
 * team's messages), the wearable's policy switches to that mechanism and this object goes.
 */
@Managed("RadioSignal")
public final class RadioSignal {
    /** Time from sending to hearing, ms. */
    static final long DELAY_MILLIS = 5;
    /** The name under root. */
    static final String NAME = "signal";

    private final CellTeam team;
    private final String sender;
    private long sent;

    RadioSignal(CellTeam team, String sender) {
        this.team = Objects.requireNonNull(team, "team");
        this.sender = Objects.requireNonNull(sender, "sender");
    }

    void install(net.smc.policy.PolicyEngine engine) {
        if (engine.root().get(NAME) == null) {
            engine.root().put(NAME, net.smc.policy.PolicyEngine.manage(this));
        }
    }

    /** Sends a distress call from {@code (x, y)} with the soldier's condition. */
    @Op("distress:y:condition:")
    public long distress(double x, double y, String condition) {
        if (!Double.isFinite(x) || !Double.isFinite(y) || condition == null || condition.isBlank()) {
            throw new PonderError("RadioSignal distress:y:condition: needs a finite position and a condition, got "
                    + x + ", " + y + ", '" + condition + "'");
        }
        var radio = team.world().world().radio();
        for (String vehicle : team.vehicles().stream().map(SimVehicle::id).toList()) {
            if (vehicle.equals(sender) || !team.isLive(vehicle)
                    || !radio.reachable(team.address(sender), team.address(vehicle))) {
                continue;
            }
            team.scheduler().schedule(DELAY_MILLIS, () -> hear(vehicle, x, y, condition));
        }
        return ++sent;
    }

    private void hear(String vehicle, double x, double y, String condition) {
        Cell cell = team.cell(vehicle);
        if (cell != null) {
            cell.engine().raise("root/event/distress", x, y, condition);
        }
    }
}
