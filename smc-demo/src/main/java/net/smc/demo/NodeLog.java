package net.smc.demo;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import net.smc.core.cell.CellEvent;

/**
 * What {@code smc node} writes on standard output, one flushed line at a time so that a reader of a
 * pipe or a log file sees each decision as it happens:
 * <ul>
 *   <li>first, the {@linkplain #up up line} ({@code up: vehicle ...}), once the node's sockets are bound;</li>
 *   <li>every decision of the cell, as {@link CellEvent#toString()} gives it (time in epoch ms,
 *       vehicle, kind, detail);</li>
 *   <li>what policies print ({@code root print:}), each line prefixed {@value #POLICY_PREFIX};</li>
 *   <li>last, a {@code down: ...} line when it stops.</li>
 * </ul>
 * Decisions the cell makes while it starts (an acting commander's {@code COMMANDING}) come before the
 * node can say it is up; they are held back and written right after the up line, so the up line is
 * always the first. Called from the cell's thread and the command's thread alike.
 */
final class NodeLog {
    static final String POLICY_PREFIX = "policy: ";

    private final PrintWriter out;
    /** Lines that came before the up line; null once it is written. */
    private List<String> early = new ArrayList<>();

    NodeLog(PrintWriter out) {
        this.out = out;
    }

    /** Writes the up line, then what was held back. */
    synchronized void up(String line) {
        write(line);
        early.forEach(this::write);
        early = null;
    }

    /** One decision of the cell. */
    synchronized void event(CellEvent event) {
        emit(event.toString());
    }

    /** What a policy printed; each of its lines is prefixed. */
    synchronized void policy(String text) {
        text.lines().forEach(line -> emit(POLICY_PREFIX + line));
    }

    /** A line of the node itself (its last line, say), written at once. */
    synchronized void line(String line) {
        write(line);
    }

    private void emit(String line) {
        if (early != null) {
            early.add(line);
        } else {
            write(line);
        }
    }

    private void write(String line) {
        out.println(line);
        out.flush();
    }
}
