package net.smc.sim.experiment;

import java.io.IOException;
import java.io.Writer;
import java.util.Locale;

/** Writes {@link SetupResult}s as CSV, one row per run, under {@link #HEADER}. */
public final class SetupTimeCsv {
    /** The columns; {@code setup_ms} is empty for a run in which not every role started. */
    public static final String HEADER = "roles,scheme,transport,run,setup_ms,messages,bytes,busiest_cpu_ms,started";

    private SetupTimeCsv() {
    }

    public static void writeHeader(Writer out) throws IOException {
        out.write(HEADER + "\n");
    }

    public static void writeRow(Writer out, SetupResult r) throws IOException {
        out.write(String.format(Locale.ROOT, "%d,%s,%s,%d,%s,%d,%d,%.3f,%d%n", r.roles(),
                r.scheme().name().toLowerCase(Locale.ROOT), r.transport(), r.run(),
                r.complete() ? String.format(Locale.ROOT, "%.1f", r.setupMillis()) : "", r.messages(), r.bytes(),
                r.busiestCpuMillis(), r.started()));
    }
}
