package net.smc.sim.scenario;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;

import net.smc.core.cell.Cell;
import net.smc.sim.render.Timeline;
import net.smc.sim.team.SimVehicle;
import net.smc.sim.team.CellTeam;

/** A scenario's timeline, each row also passed to a printer as it is recorded; and the cells' diagnostics. */
final class ScenarioLog {
    private final Timeline timeline = new Timeline();
    private final Consumer<Timeline.Row> printer;

    ScenarioLog(Consumer<Timeline.Row> printer) {
        this.printer = Objects.requireNonNull(printer, "printer");
    }

    void row(long millis, String vehicle, String what, String detail) {
        row(millis, vehicle, what, detail, "");
    }

    void row(long millis, String vehicle, String what, String detail, String step) {
        timeline.record(millis, vehicle, what, detail, step);
        List<Timeline.Row> rows = timeline.rows();
        printer.accept(rows.get(rows.size() - 1));
    }

    Timeline timeline() {
        return timeline;
    }

    /** What each live cell's policies reported as errors (a policy denied, a failed send ...), by vehicle. */
    static Map<String, List<String>> diagnostics(CellTeam team) {
        Map<String, List<String>> out = new LinkedHashMap<>();
        for (SimVehicle v : team.vehicles()) {
            Cell c = team.cell(v.id());
            if (c != null && !c.diagnostics().isEmpty()) {
                out.put(v.id(), c.diagnostics().stream().map(Object::toString).toList());
            }
        }
        return out;
    }

    /** One timeline row as a line: {@code  12.345 s  r1        STOPPED   (iv) detail}. */
    static String format(Timeline.Row r) {
        return String.format(Locale.ROOT, "%8.3f s  %-8s %-14s %-6s %s", r.timeMillis() / 1000.0, r.vehicle(), r.what(),
                r.step().isEmpty() ? "" : "(" + r.step() + ")", r.detail());
    }
}
