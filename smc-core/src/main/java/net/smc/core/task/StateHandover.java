package net.smc.core.task;

import java.util.Map;

/**
 * A task whose state is worth handing over when its role is re-assigned (the paper's Table II:
 * the failed surveyor's last position and what it had mapped). The cell reports the state of every
 * running task that implements this to its parent with its periodic report; when the vehicle fails,
 * its replacement's task of the same name imports what was last reported.
 *
 * <p>State is simple values only, so it fits a report and a PonderTalk value: strings, numbers,
 * booleans, and lists and maps (string keys) of them. Numbers may come back as {@code BigDecimal}.
 */
public interface StateHandover {

    /** The state to hand over now; a fresh map the caller may keep. */
    Map<String, Object> exportState();

    /**
     * Takes over the state another instance of the same task exported; keys it does not know are
     * ignored, so an older exporter's state still loads.
     *
     * @throws IllegalArgumentException naming the entry, when a known entry is malformed
     */
    void importState(Map<String, ?> state);
}
