package net.smc.sim.task;

import java.util.ArrayList;
import java.util.List;

import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.map.Point;

/**
 * Where failed teammates' bodies lie, as an {@link Explorer} or a {@link Navigator} was told
 * ({@code pushAside:y:}).
 * A dead robot's body can be pushed, so its cells may be planned through, and the unknown cells just
 * beyond it may lie behind the body rather than behind a wall.
 */
final class FailedBodies {
    /** A failed teammate's cells within this of its reported position are taken for its body, m. */
    static final double BODY_REACH = 0.45;
    /** Unknown cells this close to a body may lie behind the body, not a wall, m. */
    static final double BEHIND_BODY = 1.0;

    private final List<Point> bodies = new ArrayList<>();

    /** How close a body told of again must lie to one already known to be taken for it, m. */
    static final double SAME_BODY = 0.05;

    /** Adds a body unless one is known within {@link #SAME_BODY} of it (told again); whether it was new. */
    boolean add(Point body) {
        for (Point b : bodies) {
            if (b.distanceTo(body.x(), body.y()) <= SAME_BODY) {
                return false;
            }
        }
        return bodies.add(body);
    }

    /**
     * A body the robot pushed ({@code body}, as it was known) lies at {@code now}: its cells are
     * taken for the body there, no longer where it was. A body not known (told of again meanwhile
     * at another place) changes nothing.
     */
    void moved(Point body, Point now) {
        int i = bodies.indexOf(body);
        if (i >= 0) {
            bodies.set(i, now);
        }
    }

    boolean isEmpty() {
        return bodies.isEmpty();
    }

    /** The bodies' positions, for the path follower, which may push into them. */
    List<Point> points() {
        return List.copyOf(bodies);
    }

    /** Whether the centre of cell (c, r) of {@code map} is within a body's reach. */
    boolean on(OccupancyGrid map, int c, int r) {
        return near(map, c, r, BODY_REACH);
    }

    /** Whether the centre of cell (c, r) of {@code map} may lie behind a body. */
    boolean behind(OccupancyGrid map, int c, int r) {
        return near(map, c, r, BEHIND_BODY);
    }

    private boolean near(OccupancyGrid map, int c, int r, double metres) {
        Point p = map.centre(c, r);
        for (Point body : bodies) {
            if (p.distanceTo(body.x(), body.y()) <= metres) {
                return true;
            }
        }
        return false;
    }

    /** A copy of {@code map} with the bodies' cells taken for free: the map on which to plan a push. */
    OccupancyGrid without(OccupancyGrid map) {
        OccupancyGrid view = map.copy();
        int reach = (int) Math.ceil(BODY_REACH / map.resolution());
        for (Point body : bodies) {
            for (int r = map.row(body.y()) - reach; r <= map.row(body.y()) + reach; r++) {
                for (int c = map.col(body.x()) - reach; c <= map.col(body.x()) + reach; c++) {
                    if (!map.inside(c, r)) {
                        continue;
                    }
                    Point p = map.centre(c, r);
                    while (p.distanceTo(body.x(), body.y()) <= BODY_REACH && view.isOccupied(c, r)) {
                        view.markFree(p.x(), p.y());
                    }
                }
            }
        }
        return view;
    }
}
