package net.smc.demo;

import java.awt.Color;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;

import net.smc.sim.experiment.SetupResult;

/**
 * The set-up time chart (the paper's Fig. 8): per scheme and transport, the median set-up time
 * against the number of roles, on a logarithmic x axis, with the band from the 10th to the 90th
 * percentile (nearest rank) of the runs. Runs in which not every role started are left out.
 */
final class SetupTimeChart {
    private static final Color[] COLOURS = {new Color(0x1f77b4), new Color(0xd62728), new Color(0x2ca02c),
        new Color(0x9467bd)};

    private SetupTimeChart() {
    }

    /** Writes the chart of {@code results} as a PNG at {@code file} (".png" is added if missing). */
    static void write(List<SetupResult> results, Path file) throws IOException {
        XYChart chart = new XYChartBuilder().width(800).height(520).title("Mission set-up time vs number of roles")
                .xAxisTitle("roles").yAxisTitle("set-up time (s)").build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNW);
        Map<String, Map<Integer, List<Double>>> series = new TreeMap<>();
        for (SetupResult r : results) {
            if (r.complete()) {
                String name = r.scheme().name().toLowerCase(java.util.Locale.ROOT) + " (" + r.transport() + ")";
                series.computeIfAbsent(name, k -> new TreeMap<>()).computeIfAbsent(r.roles(), k -> new ArrayList<>())
                        .add(r.setupMillis() / 1_000);
            }
        }
        int colour = 0;
        for (Map.Entry<String, Map<Integer, List<Double>>> s : series.entrySet()) {
            Color c = COLOURS[colour++ % COLOURS.length];
            List<Double> xs = new ArrayList<>();
            List<Double> median = new ArrayList<>();
            List<Double> low = new ArrayList<>();
            List<Double> high = new ArrayList<>();
            for (Map.Entry<Integer, List<Double>> p : s.getValue().entrySet()) {
                double[] v = p.getValue().stream().mapToDouble(Double::doubleValue).sorted().toArray();
                xs.add((double) p.getKey());
                median.add(rank(v, 0.5));
                low.add(rank(v, 0.1));
                high.add(rank(v, 0.9));
            }
            List<Double> bandX = new ArrayList<>(xs);
            List<Double> bandY = new ArrayList<>(high);
            for (int i = xs.size() - 1; i >= 0; i--) {
                bandX.add(xs.get(i));
                bandY.add(low.get(i));
            }
            XYSeries band = chart.addSeries(s.getKey() + " p10-p90", bandX, bandY);
            band.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.PolygonArea);
            band.setFillColor(new Color(c.getRed(), c.getGreen(), c.getBlue(), 60));
            band.setLineColor(new Color(0, 0, 0, 0));
            band.setMarker(SeriesMarkers.NONE);
            band.setShowInLegend(false);
            XYSeries line = chart.addSeries(s.getKey() + " median", xs, median);
            line.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
            line.setLineColor(c);
            line.setMarkerColor(c);
            line.setMarker(SeriesMarkers.CIRCLE);
        }
        if (series.isEmpty()) {
            chart.addSeries("no complete run", new double[] {1}, new double[] {0});
        }
        BitmapEncoder.saveBitmap(chart, file.toString().replaceFirst("\\.png$", ""), BitmapEncoder.BitmapFormat.PNG);
    }

    /** Nearest-rank percentile of sorted values. */
    static double rank(double[] sorted, double q) {
        int i = (int) Math.ceil(q * sorted.length) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, i))];
    }

    static double[] sortedCopy(List<Double> v) {
        double[] a = v.stream().mapToDouble(Double::doubleValue).toArray();
        Arrays.sort(a);
        return a;
    }
}
