package net.smc.gradle

/**
 * One text table of JMH results (the parsed entries of JMH's {@code -rf json} files): a row per
 * benchmark and parameter set, its secondary results (JMH {@code @AuxCounters}, {@code -prof gc})
 * on indented rows under it.
 */
class JmhTable {
    static String format(List results) {
        def rows = [['module', 'benchmark', 'params', 'mode', 'cnt', 'score', 'error', 'units']]
        results.each { r ->
            def params = (r.params ?: [:]).collect { k, v -> "$k=$v" }.join(',')
            def name = r.benchmark.tokenize('.').takeRight(2).join('.')
            def m = r.primaryMetric
            rows << [r.module ?: '', name, params, r.mode, "${m.rawData ? m.rawData.flatten().size() : ''}",
                     number(m.score), error(m.scoreError), m.scoreUnit]
            (r.secondaryMetrics ?: [:]).each { String k, s ->
                rows << ['', "  :$k", '', '', '', number(s.score), error(s.scoreError), s.scoreUnit]
            }
        }
        def widths = (0..<rows[0].size()).collect { c -> rows.collect { it[c].toString().length() }.max() }
        rows.collect { row ->
            row.withIndex().collect { cell, c ->
                def s = cell.toString()
                c >= 4 && c <= 6 ? s.padLeft(widths[c]) : s.padRight(widths[c])
            }.join('  ').replaceAll(/\s+$/, '')
        }.join('\n')
    }

    private static String number(x) {
        if (x == null || x == 'NaN' || (x instanceof Number && Double.isNaN(x as double))) {
            return 'NaN'
        }
        double d = x as double
        Math.abs(d) >= 100 ? String.format(Locale.ROOT, '%,.0f', d)
                : Math.abs(d) >= 1 ? String.format(Locale.ROOT, '%.2f', d) : String.format(Locale.ROOT, '%.4f', d)
    }

    private static String error(x) {
        x == null || x == 'NaN' || (x instanceof Number && Double.isNaN(x as double)) ? '' : "± ${number(x)}"
    }
}
