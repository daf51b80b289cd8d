package net.smc.sim.world;

import java.nio.file.Path;

import net.smc.core.transport.sim.SimulationScheduler;
import net.smc.sim.arena.Arena;
import net.smc.sim.arena.ArenaException;
import net.smc.sim.arena.ArenaReader;

/** Test helpers: arenas from text, the shipped world files, worlds on a fresh scheduler. */
public final class Worlds {
    private Worlds() {
    }

    /** The project's root (set by the build; the working directory otherwise). */
    public static Path projectDir() {
        String dir = System.getProperty("smc.project.dir");
        return dir != null ? Path.of(dir) : Path.of("..");
    }

    public static Path worldFile(String name) {
        return projectDir().resolve("missions/worlds").resolve(name);
    }

    /** An arena from the body of a {@code <world>} element of the given size, with one start "s" at (x, y, heading°). */
    public static Arena arena(double width, double height, String body) {
        try {
            return ArenaReader.parse(Path.of("test.xml"),
                    "<world name='test' width='" + width + "' height='" + height + "'>" + body + "</world>");
        } catch (ArenaException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    public static SimWorld world(Arena arena, long seed) {
        return SimWorld.builder(arena, new SimulationScheduler()).seed(seed).build();
    }

    public static Arena.Start start(double x, double y, double headingDegrees) {
        return new Arena.Start("s", x, y, Math.toRadians(headingDegrees));
    }
}
