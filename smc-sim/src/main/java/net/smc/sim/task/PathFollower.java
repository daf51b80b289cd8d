package net.smc.sim.task;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import net.smc.sim.hardware.Drive;
import net.smc.sim.hardware.Pose;
import net.smc.sim.hardware.ProximitySensors;
import net.smc.sim.hardware.RobotHardware;
import net.smc.sim.map.Point;

/**
 * Drives a robot along waypoints with a simple unicycle controller: turn towards the next
 * waypoint (in place when it lies far off the heading), drive forward as the heading error allows,
 * and stop short of anything the forward infrared sensors see closer than the stop distance.
 */
final class PathFollower {
    /** The outcome of one control step. */
    enum Status { IDLE, MOVING, ARRIVED, OBSTRUCTED }

    private static final double TURN_GAIN = 2.5;
    private static final double IN_PLACE = Math.toRadians(60);
    private static final double FORWARD_CONE = Math.toRadians(50);

    private final RobotHardware robot;
    private final double waypointTolerance;
    private final double stopDistance;
    private final List<Point> path = new ArrayList<>();
    private double arriveTolerance;
    private final List<Point> pushable = new ArrayList<>();
    /** The body the last step pushed and where it was taken to lie then, or null ({@link #takePush}). */
    private Push pushed;

    /**
     * A push: the body as the robot knew it ({@code body}) lies, as far as the robot can tell,
     * just in front of it ({@code now}): what its front sensors read, a body's half-width further.
     */
    record Push(Point body, Point now) {
    }

    PathFollower(RobotHardware robot, double waypointTolerance, double stopDistance) {
        this.robot = robot;
        this.waypointTolerance = waypointTolerance;
        this.stopDistance = stopDistance;
    }

    void follow(List<Point> waypoints, double arriveTolerance) {
        path.clear();
        path.addAll(waypoints);
        this.arriveTolerance = arriveTolerance;
    }

    /**
     * Bodies the robot may push (failed teammates' positions): something in front within
     * {@link #PUSH_NEAR} of one of them does not stop the robot, which drives on at
     * {@link #PUSH_SPEED} of its top speed instead.
     */
    void pushable(List<Point> bodies) {
        pushable.clear();
        pushable.addAll(bodies);
    }

    /** The push of the last step, if it pushed, and forgets it: where the body it pushed now lies. */
    Optional<Push> takePush() {
        Push p = pushed;
        pushed = null;
        return Optional.ofNullable(p);
    }

    /** How near a pushable body the robot must be for what is in front of it to be taken for that body, m. */
    static final double PUSH_NEAR = 0.7;
    /** The fraction of its top speed at which the robot pushes. */
    static final double PUSH_SPEED = 0.3;

    /** Half the width of a robot's body, m: from the front sensors to a pushed body's centre, and from the robot's centre to its front. */
    static final double HALF_BODY = 0.16;
    /** The farthest a pushed body is taken to have slid from where it was last known, m. */
    static final double MAX_SLIDE = FailedBodies.BODY_REACH;
    /** How far the robot must have moved on while pushing for what is in front to be taken to have given way, m. */
    static final double GAVE_WAY = 0.05;
    /** Where the robot stood when it began the push under way (or last moved the body), or null when not pushing. */
    private Point pushStart;
    private boolean pushing;

    /** The index of the nearest pushable body within {@link #PUSH_NEAR} of the robot, or -1. */
    private int besidePushable(Pose pose) {
        int nearest = -1;
        double best = PUSH_NEAR;
        for (int i = 0; i < pushable.size(); i++) {
            double d = pushable.get(i).distanceTo(pose.x(), pose.y());
            if (d <= best) {
                best = d;
                nearest = i;
            }
        }
        return nearest;
    }

    void clear() {
        path.clear();
    }

    boolean active() {
        return !path.isEmpty();
    }

    List<Point> remaining() {
        return List.copyOf(path);
    }

    /** The smallest reading of the sensors facing forward, m (the range when nothing is seen). */
    static double frontClearance(RobotHardware robot) {
        if (!robot.has(RobotHardware.Device.PROXIMITY)) {
            return Double.POSITIVE_INFINITY;
        }
        ProximitySensors ir = robot.proximity();
        double[] r = ir.read();
        double min = ir.range();
        for (int i = 0; i < r.length; i++) {
            if (Math.abs(angleDiff(ir.angle(i), 0)) <= FORWARD_CONE) {
                min = Math.min(min, r[i]);
            }
        }
        return min;
    }

    Status step() {
        Status status = move();
        if (!pushing) {
            pushStart = null;
        }
        pushing = false;
        return status;
    }

    private Status move() {
        Drive drive = robot.drive();
        if (path.isEmpty()) {
            return Status.IDLE;
        }
        Pose pose = robot.odometry().pose();
        while (path.size() > 1 && path.get(0).distanceTo(pose.x(), pose.y()) <= waypointTolerance) {
            path.remove(0);
        }
        Point target = path.get(0);
        double distance = target.distanceTo(pose.x(), pose.y());
        if (path.size() == 1 && distance <= arriveTolerance) {
            path.clear();
            drive.stop();
            return Status.ARRIVED;
        }
        double error = angleDiff(Math.atan2(target.y() - pose.y(), target.x() - pose.x()), pose.heading());
        double max = drive.maxSpeed();
        double forward = Math.abs(error) > IN_PLACE ? 0 : max * 0.8 * Math.cos(error) * Math.min(1, distance / 0.5 + 0.2);
        double front = frontClearance(robot);
        if (forward > 0 && front < stopDistance) {
            int body = besidePushable(pose);
            if (body < 0) {
                drive.stop();
                return Status.OBSTRUCTED;
            }
            forward = Math.min(forward, max * PUSH_SPEED);
            // Where what is in front lies. It is taken for the body only if it gives way (the robot
            // has moved on since it began to push: into a jamb or a wall it stands still) and lies
            // near where the body was known (a body slides, it does not jump).
            double ahead = HALF_BODY + front + HALF_BODY;
            Point now = new Point(pose.x() + Math.cos(pose.heading()) * ahead, pose.y() + Math.sin(pose.heading()) * ahead);
            if (pushStart == null) {
                pushStart = new Point(pose.x(), pose.y());
            } else if (pushStart.distanceTo(pose.x(), pose.y()) >= GAVE_WAY
                    && now.distanceTo(pushable.get(body).x(), pushable.get(body).y()) <= MAX_SLIDE) {
                pushed = new Push(pushable.get(body), now);
                pushable.set(body, now);
                pushStart = new Point(pose.x(), pose.y());
            }
            pushing = true;
        }
        double turn = TURN_GAIN * error;
        double half = drive.wheelBase() / 2;
        double left = forward - turn * half;
        double right = forward + turn * half;
        double scale = Math.max(1, Math.max(Math.abs(left), Math.abs(right)) / max);
        drive.setWheelSpeeds(left / scale, right / scale);
        return Status.MOVING;
    }

    /** a - b, wrapped into (-pi, pi]. */
    static double angleDiff(double a, double b) {
        double d = a - b;
        while (d > Math.PI) {
            d -= 2 * Math.PI;
        }
        while (d <= -Math.PI) {
            d += 2 * Math.PI;
        }
        return d;
    }
}
