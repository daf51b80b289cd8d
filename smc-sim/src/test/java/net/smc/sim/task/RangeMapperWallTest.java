package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.robot.KoalaSpec;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.WorldStepListener;
import net.smc.sim.world.Worlds;
import org.junit.jupiter.api.Test;

/**
 * A wall on the line x = 5 between two grid columns, in the physics world with the house's ring
 * (16 beams reaching 2 m): a robot drives north beside it, and both ways of mapping see the same
 * readings. {@link RangeMapper#observe} (the Explorer's) frees cells of the column beside the
 * wall that its ring marked a moment before: rays at a shallow angle to the wall, hitting it
 * farther along, cross them. {@link RangeMapper#observeKeepingWalls} (a Navigator's) keeps them.
 */
class RangeMapperWallTest {
    private static final String WALL = "<wall x1='5' y1='0' x2='5' y2='6'/><start id='s0' x='4.66' y='0.6'/>";

    /** The rows' centres (y) of the cells west of the wall, from y 1 to 3, that a map shows free. */
    private static List<Double> gaps(OccupancyGrid map) {
        List<Double> free = new ArrayList<>();
        int col = map.col(4.9);
        for (int r = map.row(1.0); r <= map.row(3.0); r++) {
            if (map.isFree(col, r)) {
                free.add(map.centre(col, r).y());
            }
        }
        return free;
    }

    @Test
    void aRobotDrivingBesideAWallOnAGridLine_keepsTheWallOnADrivingMap_butWearsItAwayOnTheExplorersMap() {
        SimulationScheduler clock = new SimulationScheduler();
        SimWorld world = SimWorld.builder(Worlds.arena(10, 6, WALL), clock).seed(5).build();
        SimRobot robot = world.addRobot("d1", Worlds.start(4.66, 0.6, 90), KoalaSpec.koala().withIrRange(2.0));
        OccupancyGrid explorers = new OccupancyGrid(0, 0, 10, 6, 0.25);
        OccupancyGrid driving = new OccupancyGrid(0, 0, 10, 6, 0.25);
        world.addListener(new WorldStepListener() {
            @Override
            public void stepped(SimWorld w) {
                if (w.steps() % 50 == 0) {   // a position fix every second, as in the house
                    robot.positionFix();
                }
                RangeMapper.observe(robot, explorers);
                RangeMapper.observeKeepingWalls(robot, driving);
                double v = robot.pose().y() < 3.5 ? 0.15 : 0;
                robot.drive().setWheelSpeeds(v, v);
            }
        });
        world.start();
        clock.runFor(30_000);
        assertTrue(robot.pose().y() > 3.3, "it drove along the wall: " + robot.pose());
        List<Double> worn = gaps(explorers);
        assertTrue(worn.size() >= 2, "the Explorer's way of mapping wears the wall away: " + worn);
        assertEquals(List.of(), gaps(driving), "cells beside the wall free on the driving map (their centres' y)");
    }
}
