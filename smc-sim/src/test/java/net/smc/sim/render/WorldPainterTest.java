package net.smc.sim.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.GraphicsEnvironment;
import java.awt.image.BufferedImage;
import java.util.HashMap;
import java.util.Map;

import net.smc.sim.robot.KoalaSpec;
import net.smc.sim.robot.SimRobot;
import net.smc.sim.arena.Arena;
import net.smc.sim.world.SimWorld;
import net.smc.sim.world.Worlds;
import org.junit.jupiter.api.Test;

class WorldPainterTest {
    private static final String ARENA = "<hazard id='h1' kind='chemical' x='6' y='4' radius='0.15' effect='0.8' disables='true'/>"
            + "<target id='soldier' kind='soldier' x='11' y='4' radius='0.25'/><start id='s0' x='0.5' y='0.5'/>";

    private static SimWorld world() {
        return Worlds.world(Worlds.arena(12, 8, ARENA), 3);
    }

    private static void assertColour(Color expected, Color actual, String what) {
        assertTrue(Pixels.near(expected, actual, 12), what + ": expected " + Pixels.hex(expected) + ", got " + Pixels.hex(actual));
    }

    @Test
    void painter_drawsHeadless() {
        assertTrue(GraphicsEnvironment.isHeadless(), "the tests run with java.awt.headless=true");
        BufferedImage image = new WorldPainter().render(world(), new Scene("t"), 320, 240);
        assertEquals(320, image.getWidth());
        assertEquals(240, image.getHeight());
    }

    @Test
    void hazardCentre_isYellow_andItsReachIsTintedBeyondTheBody() {
        SimWorld world = world();
        BufferedImage image = new WorldPainter().render(world, new Scene("t"), 1200, 860);
        Viewport v = Viewport.fit(world.arena(), 1200, 860);
        assertColour(Palette.HAZARD, Pixels.at(image, v, 6, 4), "hazard centre");
        Color ring = Pixels.at(image, v, 6, 4 - 0.5);
        assertFalse(Pixels.near(Palette.FLOOR, ring, 8), "the reach is tinted: " + Pixels.hex(ring));
        assertTrue(ring.getRed() > ring.getBlue() + 40, "the reach is yellowish: " + Pixels.hex(ring));
        assertColour(Palette.FLOOR, Pixels.at(image, v, 6, 4 - 1.2), "floor beyond the reach");
    }

    @Test
    void robots_areDrawnInTheirColoursAtTheirPoses() {
        SimWorld world = world();
        world.addRobot("a", Worlds.start(2.5, 2.5, 30), KoalaSpec.koala());
        world.addRobot("b", Worlds.start(8.5, 6.5, -90), KoalaSpec.koala());
        BufferedImage image = new WorldPainter().render(world, new Scene("t").overlays(Overlays.defaults().withLegend(false)), 900, 640);
        Viewport v = Viewport.fit(world.arena(), 900, 640);
        assertColour(Palette.robot(0), Pixels.at(image, v, 2.5, 2.5), "robot a");
        assertColour(Palette.robot(1), Pixels.at(image, v, 8.5, 6.5), "robot b");
        assertColour(Palette.FLOOR, Pixels.at(image, v, 2.5, 3.2), "floor beside robot a");
    }

    @Test
    void soldier_isDrawnAtItsPlace() {
        SimWorld world = world();
        BufferedImage image = new WorldPainter().render(world, new Scene("t"), 1200, 860);
        Viewport v = Viewport.fit(world.arena(), 1200, 860);
        assertColour(Palette.SOLDIER, Pixels.at(image, v, 11 - 0.17, 4 + 0.17), "soldier");
    }

    @Test
    void trajectory_isDrawnInTheRobotsColourAlongTheDrivenPath() {
        SimWorld world = world();
        SimRobot robot = world.addRobot("a", Worlds.start(1, 2, 0), KoalaSpec.koala());
        TrajectoryRecorder tracks = new TrajectoryRecorder(2);
        world.addListener(tracks);
        robot.drive().setWheelSpeeds(0.4, 0.4);
        for (int i = 0; i < 500; i++) {
            world.step();
        }
        assertTrue(robot.x() > 4.5, "drove to " + robot.pose());
        BufferedImage image = new WorldPainter().render(world, new Scene("t").trajectories(tracks), 1200, 860);
        Viewport v = Viewport.fit(world.arena(), 1200, 860);
        for (int k = 3; k < 8; k++) {
            double x = k * 0.5;
            TrajectoryRecorder.Point nearest = tracks.path("a").stream()
                    .min((p, q) -> Double.compare(Math.abs(p.x() - x), Math.abs(q.x() - x))).orElseThrow();
            assertColour(Palette.robot(0), Pixels.at(image, v, nearest.x(), nearest.y()), "path at x=" + x);
        }
        assertColour(Palette.FLOOR, Pixels.at(image, v, 3.3, 2.6), "floor off the path");
    }

    @Test
    void disabledRobot_carriesARedCross_andAvoidedZoneIsDashed() {
        SimWorld world = world();
        SimRobot robot = world.addRobot("a", Worlds.start(3, 6, 0), KoalaSpec.koala());
        robot.disable("hazard:h1");
        Scene scene = new Scene("t").mark(new Mark.AvoidedZone(6, 4, 2, "zone"));
        BufferedImage image = new WorldPainter().render(world, scene, 1200, 860);
        Viewport v = Viewport.fit(world.arena(), 1200, 860);
        assertColour(Palette.MARK, Pixels.at(image, v, 3, 6), "cross on the disabled robot");
        int onCircle = 0;
        for (int i = 0; i < 72; i++) {
            double a = Math.toRadians(i * 5);
            if (Pixels.near(Palette.ZONE, Pixels.at(image, v, 6 + 2 * Math.cos(a), 4 + 2 * Math.sin(a)), 40)) {
                onCircle++;
            }
        }
        assertTrue(onCircle > 15 && onCircle < 65, "dashed: some but not all of the circle is drawn, " + onCircle + " of 72");
    }

    @Test
    void roleLabels_areReadAtEachPaint() {
        SimWorld world = world();
        world.addRobot("a", Worlds.start(3, 3, 0), KoalaSpec.koala());
        Map<String, String> roles = new HashMap<>();
        Scene scene = new Scene("t").roles(RoleLabels.of(roles)).overlays(Overlays.defaults().withLegend(false));
        BufferedImage before = new WorldPainter().render(world, scene, 600, 420);
        roles.put("a", "surveyor");
        BufferedImage after = new WorldPainter().render(world, scene, 600, 420);
        assertFalse(sameImage(before, after), "a role label changes the picture");
    }

    @Test
    void overlays_drawSomethingOnlyWhenOn() {
        SimWorld world = Worlds.world(Worlds.arena(4, 3, "<cylinder id='c' x='2.3' y='1.5' radius='0.2'/><start id='s0' x='0.5' y='0.5'/>"), 3);
        world.addRobot("a", Worlds.start(1.6, 1.5, 0), KoalaSpec.koala());
        world.addRobot("b", Worlds.start(1, 0.6, 0), KoalaSpec.koala());
        world.step();
        Scene scene = new Scene("t").overlays(Overlays.defaults());
        BufferedImage plain = new WorldPainter().render(world, scene, 600, 460);
        for (Overlays on : new Overlays[] {Overlays.defaults().withIrRays(true), Overlays.defaults().withCameraCones(true),
            Overlays.defaults().withRadioLinks(true)}) {
            assertFalse(sameImage(plain, new WorldPainter().render(world, scene.overlays(on), 600, 460)), on.toString());
        }
    }

    @Test
    void tinyImage_isRefusedWithItsSize() {
        Arena arena = world().arena();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Viewport.fit(arena, 10, 300));
        assertTrue(e.getMessage().contains("10 x 300"), e.getMessage());
    }

    private static boolean sameImage(BufferedImage a, BufferedImage b) {
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                if (a.getRGB(x, y) != b.getRGB(x, y)) {
                    return false;
                }
            }
        }
        return true;
    }
}
