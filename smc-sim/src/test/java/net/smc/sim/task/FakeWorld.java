package net.smc.sim.task;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;

/**
 * A deterministic kinematic world for task tests: a walled rectangular arena with rectangular
 * obstacles, hazards (strength falling linearly from 1 at the centre to 0 at the radius), tagged
 * objects for the camera, and unicycle robots ({@link FakeRobot}). Each step first runs every
 * robot's control loops, then moves the robots; a move into an obstacle does not happen and counts
 * as a bump.
 */
final class FakeWorld {
    record Box(double minX, double minY, double maxX, double maxY) {
        boolean near(double x, double y, double r) {
            double dx = Math.max(minX - x, Math.max(0, x - maxX));
            double dy = Math.max(minY - y, Math.max(0, y - maxY));
            return Math.hypot(dx, dy) <= r;
        }
    }

    record HazardSpot(String tag, String kind, double x, double y, double radius) {
    }

    record Thing(String tag, String kind, double x, double y) {
    }

    final double width;
    final double height;
    final List<Box> boxes = new ArrayList<>();
    final List<HazardSpot> hazards = new ArrayList<>();
    final List<Thing> things = new ArrayList<>();
    final List<FakeRobot> robots = new ArrayList<>();
    double time;

    FakeWorld(double width, double height) {
        this.width = width;
        this.height = height;
    }

    FakeWorld box(double minX, double minY, double maxX, double maxY) {
        boxes.add(new Box(minX, minY, maxX, maxY));
        return this;
    }

    FakeWorld hazard(String tag, String kind, double x, double y, double radius) {
        hazards.add(new HazardSpot(tag, kind, x, y, radius));
        return this;
    }

    FakeWorld thing(String tag, String kind, double x, double y) {
        things.add(new Thing(tag, kind, x, y));
        return this;
    }

    FakeRobot robot(String id, double x, double y, double heading) {
        FakeRobot r = new FakeRobot(this, id, x, y, heading);
        robots.add(r);
        return r;
    }

    /**
     * A map of this world as a robot that has seen all of it holds it: every cell of
     * {@code resolution} known, those whose centre lies in an obstacle occupied.
     */
    net.smc.sim.map.OccupancyGrid mapped(double resolution) {
        net.smc.sim.map.OccupancyGrid map = new net.smc.sim.map.OccupancyGrid(0, 0, width, height, resolution);
        for (int r = 0; r < map.rows(); r++) {
            for (int c = 0; c < map.cols(); c++) {
                var p = map.centre(c, r);
                for (int i = 0; i < 3; i++) {
                    if (solid(p.x(), p.y())) {
                        map.markOccupied(p.x(), p.y());
                    } else {
                        map.markFree(p.x(), p.y());
                    }
                }
            }
        }
        return map;
    }

    /** Whether a point is inside an obstacle or outside the arena. */
    boolean solid(double x, double y) {
        return blocked(x, y, 0);
    }

    /** Whether a circle of radius r at (x, y) touches an obstacle or a wall. */
    boolean blocked(double x, double y, double r) {
        if (x - r < 0 || y - r < 0 || x + r > width || y + r > height) {
            return true;
        }
        for (Box b : boxes) {
            if (b.near(x, y, r)) {
                return true;
            }
        }
        return false;
    }

    void step(double dt) {
        time += dt;
        for (FakeRobot r : robots) {
            r.runLoops(time, dt);
        }
        for (FakeRobot r : robots) {
            r.move(dt);
        }
    }

    /** Steps of 0.05 s until the condition holds or {@code seconds} pass; answers whether it held. */
    boolean runUntil(BooleanSupplier done, double seconds) {
        double end = time + seconds;
        while (time < end) {
            step(0.05);
            if (done.getAsBoolean()) {
                return true;
            }
        }
        return false;
    }

    void run(double seconds) {
        runUntil(() -> false, seconds);
    }
}
