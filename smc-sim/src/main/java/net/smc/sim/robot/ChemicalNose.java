package net.smc.sim.robot;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

import net.smc.sim.hardware.ChemicalSensor;
import net.smc.sim.hardware.Pose;
import net.smc.sim.arena.Arena;

/**
 * A chemical sensor: a hazard is sensed while the robot's centre is within the hazard's radius of
 * effect plus {@link #radius()} of its centre, with a strength falling linearly from 1 at the
 * centre to 0 at that distance.
 */
final class ChemicalNose implements ChemicalSensor {
    private final SimRobot robot;

    ChemicalNose(SimRobot robot) {
        this.robot = robot;
    }

    @Override
    public double radius() {
        return robot.spec().chemicalRadius();
    }

    @Override
    public List<Reading> sense() {
        Pose p = robot.pose();
        List<Reading> readings = new ArrayList<>();
        for (Arena.Hazard h : robot.ground().arena().hazards()) {
            double reach = h.effect() + radius();
            double d = p.distanceTo(h.x(), h.y());
            if (d <= reach) {
                readings.add(new Reading("hazard:" + h.id(), h.kind(), Math.max(0, Math.min(1, 1 - d / reach))));
            }
        }
        readings.sort(Comparator.comparingDouble(Reading::strength).reversed().thenComparing(Reading::tag));
        return readings;
    }
}
