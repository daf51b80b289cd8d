package net.smc.core.cell;

import java.math.BigDecimal;
import java.util.List;

import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.api.ArrayValue;
import net.smc.policy.api.PonderError;

/**
 * {@code root/team}: the roles of the other vehicles of the team, for policies. Its sends go over
 * the network through the management tree:
 *
 * <pre>
 * root/team raise: "hazardDetected" values: #("d1" "gas" 3 4).      // publish, as a role of this cell that publishes it
 * call := root/team invoke: "report:x:y:" of: "aggregator" args: #("gas" 3 4).
 * // the answer arrives as root/event/remoteResult (call ok value error)
 * </pre>
 */
@Managed("Team")
final class TeamObject {
    private final Cell cell;

    TeamObject(Cell cell) {
        this.cell = cell;
    }

    @Op("raise:values:")
    public BigDecimal raise(String event, ArrayValue values) {
        String role = cell.publishingRole(event)
                .orElseThrow(() -> new PonderError("no role of this cell publishes '" + event + "'"));
        return BigDecimal.valueOf(cell.publish(role, event, WireValues.list(values.items())));
    }

    @Op("invoke:of:args:")
    public BigDecimal invoke(String operation, String role, ArrayValue args) {
        return invoke(operation, role, args.items());
    }

    @Op("invoke:of:")
    public BigDecimal invoke(String operation, String role) {
        return invoke(operation, role, List.of());
    }

    private BigDecimal invoke(String operation, String role, List<Object> args) {
        String caller = cell.seats().isEmpty() ? null : cell.seats().get(0).role();
        if (caller == null) {
            throw new PonderError("this cell holds no role, so it cannot invoke '" + operation + "' of role '" + role + "'");
        }
        return BigDecimal.valueOf(cell.invoke(caller, role, operation, WireValues.list(args)));
    }
}
