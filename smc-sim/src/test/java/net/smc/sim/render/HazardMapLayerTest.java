package net.smc.sim.render;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;

import net.smc.sim.map.OccupancyGrid;
import net.smc.sim.world.Worlds;
import net.smc.sim.world.SimWorld;
import org.junit.jupiter.api.Test;

/** The hazard map's layers: a map's unknown cells shaded, its occupied cells tinted, reported hazards as diamonds. */
class HazardMapLayerTest {
    @Test
    void unknownCellsAreShaded_occupiedTinted_freeLeftAsFloor_andFoundHazardsAreDiamonds() {
        SimWorld world = Worlds.world(Worlds.arena(12, 8, "<start id='s0' x='0.5' y='0.5'/>"), 3);
        OccupancyGrid map = new OccupancyGrid(0, 0, 12, 8, 0.25);
        for (double x = 0.1; x < 6; x += 0.25) {
            for (double y = 0.1; y < 8; y += 0.25) {
                map.markFree(x, y);
            }
        }
        map.markOccupied(3.1, 3.1);
        map.markOccupied(3.1, 3.1);
        Scene scene = new Scene("map").map(map).mark(new Mark.Found(9, 4, "chemical x1"))
                .overlays(Overlays.defaults().withLegend(false));
        BufferedImage image = new WorldPainter().render(world, scene, 1200, 860);
        Viewport v = Viewport.fit(world.arena(), 1200, 860);
        Color free = Pixels.at(image, v, 1.6, 5.6);
        Color unknown = Pixels.at(image, v, 10.6, 6.6);
        Color occupied = Pixels.at(image, v, 3.125, 3.125);
        Color diamond = Pixels.at(image, v, 9, 4);
        assertTrue(Pixels.near(Palette.FLOOR, free, 16), "known free floor stays floor: " + Pixels.hex(free));
        assertTrue(unknown.getRed() < Palette.FLOOR.getRed() - 60, "unknown floor is shaded: " + Pixels.hex(unknown));
        assertTrue(occupied.getBlue() > occupied.getRed() + 30, "an occupied cell is tinted blue: " + Pixels.hex(occupied));
        assertTrue(Pixels.near(Palette.FOUND, diamond, 12), "the found hazard is a magenta diamond: " + Pixels.hex(diamond));
        assertFalse(Pixels.near(Palette.FOUND, Pixels.at(image, v, 9, 5), 40), "the diamond is small");
    }
}
