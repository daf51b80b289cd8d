package net.smc.sim.map;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A rectangular occupancy grid over the arena: each square cell is unknown, free or occupied.
 * Range readings add evidence ({@link #observeRay}): the cells a ray crosses gain evidence of
 * being free, the cell it ends in (on a hit) evidence of being occupied; a hit weighs twice a miss,
 * so a single noisy miss does not erase an obstacle. Grids of the same geometry merge
 * ({@link #merge}), and a grid travels as simple values ({@link #toState()}, {@link #fromState}).
 *
 * <p>Cells are addressed by column (along x) and row (along y) from the grid's lower-left corner.
 * Not thread-safe.
 */
public final class OccupancyGrid {
    private static final int HIT = 2;
    private static final int MISS = 1;
    private static final int CAP = 6;

    private final double minX;
    private final double minY;
    private final double resolution;
    private final int cols;
    private final int rows;
    private final boolean[] known;
    private final int[] score;
    private int knownCount;
    /** How often a cell has changed between unknown, free and occupied: what {@link #toState()} shows. */
    private long changes;
    /** The rows of cells {@link #toState()} gave when {@link #changes} was {@link #linesAt} (none yet: null). */
    private List<String> lines;
    private long linesAt = -1;

    /**
     * A grid of unknown cells covering {@code width} x {@code height} metres from {@code (minX, minY)}.
     *
     * @throws IllegalArgumentException when a size is not positive, or the grid would exceed 4 million cells
     */
    public OccupancyGrid(double minX, double minY, double width, double height, double resolution) {
        if (!Double.isFinite(minX) || !Double.isFinite(minY)) {
            throw new IllegalArgumentException("grid origin (" + minX + ", " + minY + ") must be finite");
        }
        if (!(resolution > 0) || !Double.isFinite(resolution)) {
            throw new IllegalArgumentException("grid resolution " + resolution + " must be a positive number of metres");
        }
        if (!(width > 0) || !(height > 0) || !Double.isFinite(width) || !Double.isFinite(height)) {
            throw new IllegalArgumentException("grid size " + width + " x " + height + " must be positive metres");
        }
        long c = (long) Math.ceil(width / resolution - 1e-9);
        long r = (long) Math.ceil(height / resolution - 1e-9);
        if (c * r > 4_000_000L) {
            throw new IllegalArgumentException("grid of " + c + " x " + r + " cells is too large; at most 4,000,000 cells");
        }
        this.minX = minX;
        this.minY = minY;
        this.resolution = resolution;
        this.cols = (int) c;
        this.rows = (int) r;
        this.known = new boolean[cols * rows];
        this.score = new int[cols * rows];
    }

    public double minX() {
        return minX;
    }

    public double minY() {
        return minY;
    }

    public double resolution() {
        return resolution;
    }

    public int cols() {
        return cols;
    }

    public int rows() {
        return rows;
    }

    /** Whether the point lies on the grid. */
    public boolean covers(double x, double y) {
        return x >= minX && y >= minY && x < minX + cols * resolution && y < minY + rows * resolution;
    }

    /** The column of x (may be off the grid). */
    public int col(double x) {
        return (int) Math.floor((x - minX) / resolution);
    }

    /** The row of y (may be off the grid). */
    public int row(double y) {
        return (int) Math.floor((y - minY) / resolution);
    }

    public boolean inside(int col, int row) {
        return col >= 0 && row >= 0 && col < cols && row < rows;
    }

    /** The centre of a cell. */
    public Point centre(int col, int row) {
        return new Point(minX + (col + 0.5) * resolution, minY + (row + 0.5) * resolution);
    }

    public boolean isKnown(int col, int row) {
        return inside(col, row) && known[col + row * cols];
    }

    /** Known and with more evidence of an obstacle than of free space. Off the grid counts as occupied. */
    public boolean isOccupied(int col, int row) {
        if (!inside(col, row)) {
            return true;
        }
        int i = col + row * cols;
        return known[i] && score[i] > 0;
    }

    public boolean isFree(int col, int row) {
        if (!inside(col, row)) {
            return false;
        }
        int i = col + row * cols;
        return known[i] && score[i] <= 0;
    }

    /**
     * Whether an occupied cell touches this one (8-connected; off the grid does not count): a
     * frontier along a wall mostly looks into the wall, and chasing it cell by cell costs a trip
     * per cell for nothing.
     */
    public boolean besideOccupied(int col, int row) {
        for (int dr = -1; dr <= 1; dr++) {
            for (int dc = -1; dc <= 1; dc++) {
                if ((dr != 0 || dc != 0) && inside(col + dc, row + dr) && isOccupied(col + dc, row + dr)) {
                    return true;
                }
            }
        }
        return false;
    }

    /** A free cell with an unknown neighbour (4-connected): where exploring pays. */
    public boolean isFrontier(int col, int row) {
        if (!isFree(col, row)) {
            return false;
        }
        return unknownOnGrid(col + 1, row) || unknownOnGrid(col - 1, row)
                || unknownOnGrid(col, row + 1) || unknownOnGrid(col, row - 1);
    }

    private boolean unknownOnGrid(int col, int row) {
        return inside(col, row) && !known[col + row * cols];
    }

    /** How many cells are known. */
    public int knownCells() {
        return knownCount;
    }

    /** The share of cells known, 0..1. */
    public double exploredFraction() {
        return (double) knownCount / (cols * rows);
    }

    /** Adds evidence that the cell at the point is free; points off the grid are ignored. */
    public void markFree(double x, double y) {
        add(col(x), row(y), -MISS);
    }

    /** Adds evidence that the cell at the point is occupied; points off the grid are ignored. */
    public void markOccupied(double x, double y) {
        add(col(x), row(y), HIT);
    }

    private void add(int col, int row, int evidence) {
        if (!inside(col, row)) {
            return;
        }
        int i = col + row * cols;
        boolean wasOccupied = score[i] > 0;
        if (!known[i]) {
            known[i] = true;
            knownCount++;
            changes++;
        }
        score[i] = Math.max(-CAP, Math.min(CAP, score[i] + evidence));
        if (wasOccupied != score[i] > 0) {
            changes++;
        }
    }

    /**
     * One range reading from {@code (x0, y0)} to {@code (x1, y1)}: the cells before the end gain
     * evidence of being free, the end cell evidence of an obstacle if {@code hit}, else of free space.
     */
    public void observeRay(double x0, double y0, double x1, double y1, boolean hit) {
        int c = col(x0);
        int r = row(y0);
        int endC = col(x1);
        int endR = row(y1);
        int dc = Math.abs(endC - c);
        int dr = -Math.abs(endR - r);
        int sc = c < endC ? 1 : -1;
        int sr = r < endR ? 1 : -1;
        int err = dc + dr;
        while (c != endC || r != endR) {
            add(c, r, -MISS);
            int e2 = 2 * err;
            if (e2 >= dr) {
                err += dr;
                c += sc;
            }
            if (e2 <= dc) {
                err += dc;
                r += sr;
            }
        }
        add(endC, endR, hit ? HIT : -MISS);
    }

    /** Whether {@code other} covers the same cells (origin, resolution and size). */
    public boolean sameGeometry(OccupancyGrid other) {
        return other.minX == minX && other.minY == minY && other.resolution == resolution
                && other.cols == cols && other.rows == rows;
    }

    /**
     * Merges another robot's grid into this one: a cell known there and unknown here is copied; a
     * cell known in both keeps the stronger evidence of an obstacle (a missed obstacle costs more
     * than a detour).
     *
     * @throws IllegalArgumentException when the geometries differ
     */
    public void merge(OccupancyGrid other) {
        if (!sameGeometry(other)) {
            throw new IllegalArgumentException("cannot merge a grid " + other.describe() + " into a grid " + describe()
                    + "; merged grids must have the same origin, resolution and size");
        }
        for (int i = 0; i < known.length; i++) {
            if (!other.known[i]) {
                continue;
            }
            if (!known[i]) {
                known[i] = true;
                knownCount++;
                score[i] = other.score[i];
                changes++;
            } else {
                if (score[i] <= 0 && other.score[i] > 0) {
                    changes++;
                }
                score[i] = Math.max(score[i], other.score[i]);
            }
        }
    }

    /**
     * Fills this grid's unknown cells from another robot's grid, leaving the cells it knows as they
     * are: its own observations stand (a robot the other saw in a doorway long ago, say, is not
     * taken for a wall it has since seen free).
     *
     * @throws IllegalArgumentException when the geometries differ
     */
    public void fillUnknown(OccupancyGrid other) {
        if (!sameGeometry(other)) {
            throw new IllegalArgumentException("cannot fill a grid " + describe() + " from a grid " + other.describe()
                    + "; the grids must have the same origin, resolution and size");
        }
        for (int i = 0; i < known.length; i++) {
            if (other.known[i] && !known[i]) {
                known[i] = true;
                knownCount++;
                score[i] = other.score[i];
                changes++;
            }
        }
    }

    /** A copy. */
    public OccupancyGrid copy() {
        OccupancyGrid g = new OccupancyGrid(minX, minY, cols * resolution, rows * resolution, resolution);
        g.merge(this);
        return g;
    }

    /** {@code 40x30 cells of 0.25 m from (0.0, 0.0)}, for messages. */
    public String describe() {
        return cols + "x" + rows + " cells of " + resolution + " m from (" + minX + ", " + minY + ")";
    }

    /**
     * The grid as simple values: {@code minX}, {@code minY}, {@code resolution}, {@code cols},
     * {@code rows}, and {@code cells}, one string per row from the bottom, one character per cell:
     * {@code ?} unknown, {@code .} free, {@code #} occupied. The rows are written again only when a
     * cell has changed between those three since the last call (robots export their maps with
     * every status report, and most reports find them as they were).
     */
    public Map<String, Object> toState() {
        Map<String, Object> state = new LinkedHashMap<>();
        state.put("minX", minX);
        state.put("minY", minY);
        state.put("resolution", resolution);
        state.put("cols", cols);
        state.put("rows", rows);
        if (lines == null || linesAt != changes) {
            List<String> written = new ArrayList<>(rows);
            for (int r = 0; r < rows; r++) {
                StringBuilder line = new StringBuilder(cols);
                for (int c = 0; c < cols; c++) {
                    line.append(isOccupied(c, r) ? '#' : isFree(c, r) ? '.' : '?');
                }
                written.add(line.toString());
            }
            lines = List.copyOf(written);
            linesAt = changes;
        }
        state.put("cells", new ArrayList<>(lines));
        return state;
    }

    /**
     * The grid that {@link #toState()} described.
     *
     * @throws IllegalArgumentException naming the entry when one is missing or malformed
     */
    public static OccupancyGrid fromState(Map<String, ?> state) {
        double minX = number(state, "minX");
        double minY = number(state, "minY");
        double resolution = number(state, "resolution");
        int cols = (int) number(state, "cols");
        int rows = (int) number(state, "rows");
        OccupancyGrid grid = new OccupancyGrid(minX, minY, cols * resolution, rows * resolution, resolution);
        if (grid.cols != cols || grid.rows != rows) {
            throw new IllegalArgumentException("grid state: cols " + cols + " and rows " + rows + " must be positive");
        }
        if (!(state.get("cells") instanceof List<?> lines) || lines.size() != rows) {
            throw new IllegalArgumentException("grid state: 'cells' must be a list of " + rows + " strings, one per row");
        }
        for (int r = 0; r < rows; r++) {
            if (!(lines.get(r) instanceof String line) || line.length() != cols) {
                throw new IllegalArgumentException("grid state: row " + r + " of 'cells' must be a string of " + cols
                        + " characters");
            }
            for (int c = 0; c < cols; c++) {
                switch (line.charAt(c)) {
                    case '?' -> { }
                    case '.' -> grid.add(c, r, -MISS);
                    case '#' -> grid.add(c, r, HIT);
                    default -> throw new IllegalArgumentException("grid state: row " + r + ", column " + c + " holds '"
                            + line.charAt(c) + "'; a cell is '?' (unknown), '.' (free) or '#' (occupied)");
                }
            }
        }
        return grid;
    }

    private static double number(Map<String, ?> state, String key) {
        if (!(state.get(key) instanceof Number n) || !Double.isFinite(n.doubleValue())) {
            throw new IllegalArgumentException("grid state: '" + key + "' must be a finite number, got " + state.get(key));
        }
        return n.doubleValue();
    }
}
