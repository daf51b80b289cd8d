package net.smc.sim.world;

import net.smc.sim.arena.Arena;
import net.smc.sim.arena.Thing;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.World;

/**
 * The bodies of an arena in a dyn4j {@link World}: its fence, walls, closed doors, obstacles,
 * hazards and targets, each an immovable body tagged with its {@link Thing}, built once when a
 * {@link SimWorld} is made. The robots' bodies are the world's own business.
 */
final class ArenaBodies {
    private static final double FENCE = 0.2;

    private ArenaBodies() {
    }

    static void build(Arena arena, World<Body> physics) {
        double w = arena.width();
        double h = arena.height();
        add(physics, Thing.Kind.WALL, "fence", Geometry.createRectangle(w + 2 * FENCE, FENCE), w / 2, -FENCE / 2, 0);
        add(physics, Thing.Kind.WALL, "fence", Geometry.createRectangle(w + 2 * FENCE, FENCE), w / 2, h + FENCE / 2, 0);
        add(physics, Thing.Kind.WALL, "fence", Geometry.createRectangle(FENCE, h), -FENCE / 2, h / 2, 0);
        add(physics, Thing.Kind.WALL, "fence", Geometry.createRectangle(FENCE, h), w + FENCE / 2, h / 2, 0);
        for (Arena.Wall wall : arena.walls()) {
            segment(physics, Thing.Kind.WALL, "wall", wall.x1(), wall.y1(), wall.x2(), wall.y2(), wall.thickness());
        }
        for (Arena.Door door : arena.doors()) {
            if (!door.open()) {
                segment(physics, Thing.Kind.DOOR, "door:" + door.id(), door.x1(), door.y1(), door.x2(), door.y2(),
                        door.thickness());
            }
        }
        for (Arena.Box box : arena.boxes()) {
            add(physics, Thing.Kind.OBSTACLE, box.id(), Geometry.createRectangle(box.width(), box.height()),
                    box.x(), box.y(), box.angle());
        }
        for (Arena.Cylinder c : arena.cylinders()) {
            add(physics, Thing.Kind.OBSTACLE, c.id(), Geometry.createCircle(c.radius()), c.x(), c.y(), 0);
        }
        for (Arena.Hazard hazard : arena.hazards()) {
            if (hazard.radius() > 0) {
                add(physics, Thing.Kind.HAZARD, "hazard:" + hazard.id(), Geometry.createCircle(hazard.radius()),
                        hazard.x(), hazard.y(), 0);
            }
        }
        for (Arena.Target target : arena.targets()) {
            add(physics, Thing.Kind.TARGET, target.id(), Geometry.createCircle(target.radius()),
                    target.x(), target.y(), 0);
        }
    }

    private static void segment(World<Body> physics, Thing.Kind kind, String tag, double x1, double y1,
                                double x2, double y2, double thickness) {
        double length = Math.hypot(x2 - x1, y2 - y1) + thickness;   // square ends meet at corners
        add(physics, kind, tag, Geometry.createRectangle(length, thickness), (x1 + x2) / 2, (y1 + y2) / 2,
                Math.atan2(y2 - y1, x2 - x1));
    }

    private static void add(World<Body> physics, Thing.Kind kind, String tag, Convex shape, double x, double y,
                            double angle) {
        Body body = new Body();
        BodyFixture fixture = body.addFixture(shape);
        fixture.setFriction(0.4);
        fixture.setRestitution(0);
        body.setMass(MassType.INFINITE);
        body.rotateAboutCenter(angle);
        body.translate(new Vector2(x, y));
        body.setUserData(new Thing(kind, tag));
        physics.addBody(body);
    }
}
