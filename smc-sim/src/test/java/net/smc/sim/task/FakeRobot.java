package net.smc.sim.task;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import net.smc.sim.hardware.Battery;
import net.smc.sim.hardware.Camera;
import net.smc.sim.hardware.ChemicalSensor;
import net.smc.sim.hardware.ControlLoop;
import net.smc.sim.hardware.Drive;
import net.smc.sim.hardware.Odometry;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.ProximitySensors;
import net.smc.sim.hardware.Radio;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.hardware.Sighting;

/**
 * A unicycle robot of {@link FakeWorld}: body radius 0.15 m (wheel base 0.3 m), top speed 0.5 m/s,
 * acceleration 2 m/s^2, eight infrared sensors of 0.8 m every 45 degrees, a 90 degree camera of 4 m
 * (no occlusion), a chemical sensor, and a radio whose quality falls linearly to 0 at 10 m.
 * Odometry is exact.
 */
final class FakeRobot implements RobotHardware {
    static final double WHEEL_BASE = 0.3;
    static final double MAX_SPEED = 0.5;
    static final double ACCEL = 2.0;
    static final double IR_RANGE = 0.8;
    static final double RADIO_RANGE = 10;

    private final FakeWorld world;
    private final String id;
    private final Map<Object, ControlLoop> loops = new LinkedHashMap<>();
    private final Set<Device> devices = EnumSet.allOf(Device.class);
    double x;
    double y;
    double heading;
    double travelled;
    int bumps;
    double wantLeft;   // the commanded left wheel speed (read by tests)
    double wantRight;   // the commanded right wheel speed (read by tests)
    private double left;
    private double right;
    final List<Pose> trail = new ArrayList<>();

    FakeRobot(FakeWorld world, String id, double x, double y, double heading) {
        this.world = world;
        this.id = id;
        this.x = x;
        this.y = y;
        this.heading = heading;
    }

    FakeRobot without(Device device) {
        devices.remove(device);
        return this;
    }

    int loopCount() {
        return loops.size();
    }

    void runLoops(double time, double dt) {
        for (ControlLoop loop : List.copyOf(loops.values())) {
            loop.step(time, dt);
        }
    }

    void move(double dt) {
        left = ramp(left, wantLeft, dt);
        right = ramp(right, wantRight, dt);
        double v = (left + right) / 2;
        double w = (right - left) / WHEEL_BASE;
        double nh = heading + w * dt;
        double nx = x + v * Math.cos(heading) * dt;
        double ny = y + v * Math.sin(heading) * dt;
        if (world.blocked(nx, ny, WHEEL_BASE / 2)) {
            if (v != 0) {
                bumps++;
            }
            left = 0;
            right = 0;
        } else {
            travelled += Math.abs(v) * dt;
            x = nx;
            y = ny;
        }
        heading = Math.atan2(Math.sin(nh), Math.cos(nh));
        trail.add(new Pose(x, y, heading));
    }

    private static double ramp(double now, double want, double dt) {
        double d = want - now;
        double max = ACCEL * dt;
        return now + Math.max(-max, Math.min(max, d));
    }

    double speed() {
        return (left + right) / 2;
    }

    @Override
    public String id() {
        return id;
    }

    @Override
    public boolean has(Device device) {
        return devices.contains(device);
    }

    @Override
    public Drive drive() {
        return new Drive() {
            @Override
            public void setWheelSpeeds(double l, double r) {
                wantLeft = Math.max(-MAX_SPEED, Math.min(MAX_SPEED, l));
                wantRight = Math.max(-MAX_SPEED, Math.min(MAX_SPEED, r));
            }

            @Override
            public double maxSpeed() {
                return MAX_SPEED;
            }

            @Override
            public double wheelBase() {
                return WHEEL_BASE;
            }

            @Override
            public boolean working() {
                return true;
            }
        };
    }

    @Override
    public Odometry odometry() {
        return new Odometry() {
            @Override
            public Pose pose() {
                return new Pose(x, y, heading);
            }

            @Override
            public double travelled() {
                return travelled;
            }
        };
    }

    @Override
    public ProximitySensors proximity() {
        return new ProximitySensors() {
            @Override
            public int count() {
                return 8;
            }

            @Override
            public double angle(int i) {
                return PathFollower.angleDiff(i * Math.PI / 4, 0);
            }

            @Override
            public double range() {
                return IR_RANGE;
            }

            @Override
            public double[] read() {
                double[] r = new double[8];
                for (int i = 0; i < 8; i++) {
                    double a = heading + angle(i);
                    r[i] = IR_RANGE;
                    for (double d = 0; d < IR_RANGE; d += 0.01) {
                        double px = x + Math.cos(a) * (WHEEL_BASE / 2 + d);
                        double py = y + Math.sin(a) * (WHEEL_BASE / 2 + d);
                        if (world.solid(px, py)) {
                            r[i] = d;
                            break;
                        }
                    }
                }
                return r;
            }
        };
    }

    @Override
    public Camera camera() {
        return new Camera() {
            @Override
            public double fieldOfView() {
                return Math.PI / 2;
            }

            @Override
            public double range() {
                return 4;
            }

            @Override
            public List<Sighting> look() {
                List<Sighting> seen = new ArrayList<>();
                if (!has(Device.CAMERA)) {
                    return seen;
                }
                for (FakeWorld.Thing t : world.things) {
                    see(seen, t.tag(), t.kind(), t.x(), t.y());
                }
                for (FakeRobot r : world.robots) {
                    if (r != FakeRobot.this) {
                        see(seen, r.id, "robot", r.x, r.y);
                    }
                }
                seen.sort(Comparator.comparingDouble(Sighting::distance));
                return seen;
            }

            private void see(List<Sighting> seen, String tag, String kind, double tx, double ty) {
                double d = Math.hypot(tx - x, ty - y);
                double bearing = PathFollower.angleDiff(Math.atan2(ty - y, tx - x), heading);
                if (d <= range() && Math.abs(bearing) <= fieldOfView() / 2) {
                    seen.add(new Sighting(tag, kind, bearing, d));
                }
            }
        };
    }

    @Override
    public ChemicalSensor chemical() {
        return new ChemicalSensor() {
            @Override
            public double radius() {
                return 2;
            }

            @Override
            public List<Reading> sense() {
                List<Reading> found = new ArrayList<>();
                for (FakeWorld.HazardSpot h : world.hazards) {
                    double d = Math.hypot(h.x() - x, h.y() - y);
                    if (d < h.radius()) {
                        found.add(new Reading(h.tag(), h.kind(), 1 - d / h.radius()));
                    }
                }
                found.sort(Comparator.comparingDouble(Reading::strength).reversed());
                return found;
            }
        };
    }

    @Override
    public Battery battery() {
        return () -> 1.0;
    }

    @Override
    public Radio radio() {
        return () -> {
            Map<String, Double> heard = new TreeMap<>();
            for (FakeRobot r : world.robots) {
                double d = Math.hypot(r.x - x, r.y - y);
                if (r != this && d < RADIO_RANGE) {
                    heard.put(r.id, 1 - d / RADIO_RANGE);
                }
            }
            return heard;
        };
    }

    @Override
    public void control(Object owner, ControlLoop loop) {
        if (loop == null) {
            loops.remove(owner);
        } else {
            loops.put(owner, loop);
        }
    }
}
