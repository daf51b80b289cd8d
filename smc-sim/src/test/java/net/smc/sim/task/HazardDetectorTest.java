package net.smc.sim.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class HazardDetectorTest {

    @Test
    void aHazardAboveTheThreshold_raisesHazardDetectedOnceWithTheRobotsPosition() throws Exception {
        FakeWorld world = new FakeWorld(8, 8).hazard("h1", "chemical", 3, 3, 2);
        FakeRobot robot = world.robot("r1", 3.5, 3.2, 0);
        HazardDetector detector = new HazardDetector(robot);
        EventLog log = new EventLog().watch(detector);
        detector.start();
        world.run(2);
        List<String[]> found = log.of("hazardDetected");
        assertEquals(1, found.size(), "events: " + log.lines);
        assertEquals("hazardDetected", found.get(0)[0]);
        assertEquals("r1", found.get(0)[1]);
        assertEquals("chemical", found.get(0)[2]);
        assertEquals(3.5, EventLog.num(found.get(0)[3]), 1e-9);
        assertEquals(3.2, EventLog.num(found.get(0)[4]), 1e-9);
        assertEquals(List.of(List.of("h1", "chemical", 3.5, 3.2)), detector.hazards());
    }

    @Test
    void aHazardBelowTheThreshold_raisesNothing() throws Exception {
        FakeWorld world = new FakeWorld(8, 8).hazard("h1", "chemical", 3, 3, 2);
        HazardDetector detector = new HazardDetector(world.robot("r1", 4.5, 3, 0));
        EventLog log = new EventLog().watch(detector);
        detector.start();
        world.run(1);
        assertEquals(List.of(), log.of("hazardDetected"));
        detector.threshold(0.2);
        world.run(1);
        assertEquals(1, log.of("hazardDetected").size());
    }

    @Test
    void threshold_outsideZeroToOne_isRefused() {
        HazardDetector detector = new HazardDetector(new FakeWorld(8, 8).robot("r1", 1, 1, 0));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> detector.threshold(1.5));
        assertTrue(e.getMessage().contains("threshold 1.5 must lie in 0..1"), e.getMessage());
    }

    @Test
    void handedOverReports_areNotReportedAgain() throws Exception {
        FakeWorld world = new FakeWorld(8, 8).hazard("h1", "chemical", 3, 3, 2);
        HazardDetector first = new HazardDetector(world.robot("r1", 3, 3, 0));
        first.start();
        world.run(0.2);
        HazardDetector second = new HazardDetector(world.robot("r2", 3.2, 3, 0));
        second.importState(first.exportState());
        EventLog log = new EventLog().watch(second);
        second.start();
        world.run(1);
        assertEquals(List.of(), log.of("hazardDetected"));
        assertEquals(first.hazards(), second.hazards());
    }
}
