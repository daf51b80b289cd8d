package net.smc.sim.render;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * What happened in a run, in order: one row per event (a role assigned, a robot stopped, the
 * soldier reached), fed by the scenario and written as CSV with a header line
 * {@code time_ms,vehicle,what,detail,step}, fields quoted as RFC 4180 says (a field holding a
 * comma, a quote or a line break is put in quotes, its quotes doubled), lines ended by CRLF.
 */
public final class Timeline {
    /** The CSV header line's fields. */
    public static final List<String> COLUMNS = List.of("time_ms", "vehicle", "what", "detail", "step");
    private final List<Row> rows = new ArrayList<>();

    /**
     * One event.
     *
     * @param timeMillis mission time, ms
     * @param vehicle    the vehicle it concerns ("" for the team or the world)
     * @param what       its kind, e.g. {@code ASSIGNED}, {@code DISABLED}, {@code REACHED}
     * @param detail     free text, e.g. {@code surveyor#0} or {@code hazard:h1 at (5.20, 4.01)}
     * @param step       the scenario step it belongs to, e.g. the paper's {@code iv} ("" for none)
     */
    public record Row(long timeMillis, String vehicle, String what, String detail, String step) {
        public Row {
            if (timeMillis < 0) {
                throw new IllegalArgumentException("timeline row at " + timeMillis + " ms; mission time must be 0 or more");
            }
            Objects.requireNonNull(vehicle, "vehicle");
            Objects.requireNonNull(what, "what");
            Objects.requireNonNull(detail, "detail");
            Objects.requireNonNull(step, "step");
        }
    }

    /** Adds a row. */
    public Timeline record(long timeMillis, String vehicle, String what, String detail, String step) {
        rows.add(new Row(timeMillis, vehicle, what, detail, step));
        return this;
    }

    /** The rows so far, in the order recorded. */
    public List<Row> rows() {
        return List.copyOf(rows);
    }

    /** Writes the header and every row as CSV. */
    public void writeCsv(Writer out) throws IOException {
        line(out, COLUMNS);
        for (Row row : rows) {
            line(out, List.of(Long.toString(row.timeMillis()), row.vehicle(), row.what(), row.detail(), row.step()));
        }
        out.flush();
    }

    /** Writes the CSV to {@code file}, UTF-8. */
    public void writeCsv(Path file) throws IOException {
        try (Writer out = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            writeCsv(out);
        }
    }

    private static void line(Writer out, List<String> fields) throws IOException {
        for (int i = 0; i < fields.size(); i++) {
            if (i > 0) {
                out.write(',');
            }
            out.write(quote(fields.get(i)));
        }
        out.write("\r\n");
    }

    /** A CSV field: as it is, or in double quotes with its quotes doubled when it holds a comma, quote or line break. */
    static String quote(String field) {
        boolean plain = field.chars().noneMatch(c -> c == ',' || c == '"' || c == '\n' || c == '\r');
        return plain ? field : '"' + field.replace("\"", "\"\"") + '"';
    }
}
