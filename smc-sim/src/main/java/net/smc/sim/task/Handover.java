package net.smc.sim.task;

import java.util.Map;
import net.smc.core.task.StateHandover;

/**
 * The state of a task worth handing over when its role is re-assigned (the paper's Table II: the
 * failed surveyor's last position and what it had mapped). The state is simple values only, so it
 * fits a heartbeat's report and a PonderTalk hash: strings, numbers, booleans, and lists and maps
 * of them. The cell hands it over through {@link StateHandover}.
 */
public interface Handover extends StateHandover {

    /** The state to hand over now; a fresh map the caller may keep. */
    @Override
    Map<String, Object> exportState();

    /**
     * Takes over the state another instance of the same task exported; keys it does not know are
     * ignored, so an older exporter's state still loads.
     *
     * @throws IllegalArgumentException naming the entry, when a known entry is malformed
     */
    @Override
    void importState(Map<String, ?> state);
}
