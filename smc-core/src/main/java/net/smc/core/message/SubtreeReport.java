package net.smc.core.message;

import java.util.List;

/**
 * A child's periodic report to its parent: its primary role and, as alternating keys and
 * PonderTalk values, the holders per role in its subtree, the seats it claims and the state worth
 * handing over if it fails (its last position, its tasks' state). Connectionless: it repeats.
 */
public record SubtreeReport(String role, List<Object> values) implements Message {
    public SubtreeReport {
        Fields.name("SubtreeReport.role", role);
        values = ValueLimits.list("SubtreeReport.values", values);
    }

    @Override
    public MessageType type() {
        return MessageType.SUBTREE_REPORT;
    }
}
