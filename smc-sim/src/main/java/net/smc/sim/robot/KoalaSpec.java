package net.smc.sim.robot;

/**
 * The build of a simulated Koala-like robot: body, drive, sensors, noise and battery. Lengths in
 * metres, speeds in m/s, angles in radians, noise as standard deviations, endurance in seconds.
 *
 * <p>{@link #koala()} follows the K-Team Koala the paper's demonstration used (section IV-C): a
 * six-wheeled skid-steered body about 32 cm square weighing about 4 kg, two DC motors (one per
 * side, wheels of 82.5 mm), a top speed of about 0.6 m/s, sixteen infrared proximity sensors
 * around the body reaching about 20 cm, a camera, and a NiMH pack good for about three hours of
 * driving. The acceleration limit, the noise figures, the camera's field of view and range and the
 * chemical sensor (which the Koala did not carry; the demonstration's hazard was detected on
 * sight) are modelling choices, not K-Team figures.
 *
 * @param length            body length along the heading, m
 * @param width             body width, m
 * @param mass              kg
 * @param wheelBase         distance between the left and right wheel tracks, m
 * @param maxSpeed          top wheel speed, m/s
 * @param maxAcceleration   how fast a wheel's speed may change, m/s^2
 * @param irRange           infrared sensors' range from the body's edge, m
 * @param irNoise           infrared reading noise, m
 * @param cameraFov         the camera's full field of view, rad
 * @param cameraRange       the camera's range, m
 * @param cameraNoise       noise on a sighting's distance, m (a tenth of it, in rad, on its bearing)
 * @param chemicalRadius    how far beyond a hazard's radius of effect its substance is sensed, m
 * @param odometryNoise     each wheel's speed error as counted by its encoder, a fraction of the speed
 * @param enduranceMoving   battery life driving both wheels at top speed, s
 * @param enduranceIdle     battery life standing still, s
 */
public record KoalaSpec(double length, double width, double mass, double wheelBase, double maxSpeed,
                        double maxAcceleration, double irRange, double irNoise, double cameraFov, double cameraRange,
                        double cameraNoise, double chemicalRadius, double odometryNoise, double enduranceMoving,
                        double enduranceIdle) {

    /** The 16 infrared sensors' directions, degrees from the heading: dense at the front, as on the Koala. */
    private static final double[] IR_DEGREES = {
        8, 25, 45, 62, 80, 100, 135, 170, -170, -135, -100, -80, -62, -45, -25, -8};

    public KoalaSpec {
        positive("length", length);
        positive("width", width);
        positive("mass", mass);
        positive("wheelBase", wheelBase);
        positive("maxSpeed", maxSpeed);
        positive("maxAcceleration", maxAcceleration);
        positive("irRange", irRange);
        notNegative("irNoise", irNoise);
        if (!(cameraFov > 0 && cameraFov < 2 * Math.PI)) {
            throw new IllegalArgumentException("cameraFov " + cameraFov + " is out of range; it must be above 0 and below 2 pi");
        }
        positive("cameraRange", cameraRange);
        notNegative("cameraNoise", cameraNoise);
        notNegative("chemicalRadius", chemicalRadius);
        notNegative("odometryNoise", odometryNoise);
        positive("enduranceMoving", enduranceMoving);
        positive("enduranceIdle", enduranceIdle);
        if (enduranceIdle < enduranceMoving) {
            throw new IllegalArgumentException("enduranceIdle " + enduranceIdle + " s is below enduranceMoving "
                    + enduranceMoving + " s; a battery lasts longer standing still");
        }
    }

    /** The Koala as the paper's demonstration used it (see the class comment for sources). */
    public static KoalaSpec koala() {
        return new KoalaSpec(0.32, 0.32, 4.0, 0.26, 0.6, 1.0, 0.20, 0.005,
                Math.toRadians(60), 6.0, 0.02, 1.0, 0.02, 3 * 3600, 12 * 3600);
    }

    /** This spec with other odometry noise. */
    public KoalaSpec withOdometryNoise(double fraction) {
        return new KoalaSpec(length, width, mass, wheelBase, maxSpeed, maxAcceleration, irRange, irNoise, cameraFov,
                cameraRange, cameraNoise, chemicalRadius, fraction, enduranceMoving, enduranceIdle);
    }

    /** This spec with other infrared noise. */
    public KoalaSpec withIrNoise(double metres) {
        return new KoalaSpec(length, width, mass, wheelBase, maxSpeed, maxAcceleration, irRange, metres, cameraFov,
                cameraRange, cameraNoise, chemicalRadius, odometryNoise, enduranceMoving, enduranceIdle);
    }

    /** This spec with proximity sensors of another range, m (from the body's edge). */
    public KoalaSpec withIrRange(double metres) {
        return new KoalaSpec(length, width, mass, wheelBase, maxSpeed, maxAcceleration, metres, irNoise, cameraFov,
                cameraRange, cameraNoise, chemicalRadius, odometryNoise, enduranceMoving, enduranceIdle);
    }

    /** This spec with another battery. */
    public KoalaSpec withEndurance(double movingSeconds, double idleSeconds) {
        return new KoalaSpec(length, width, mass, wheelBase, maxSpeed, maxAcceleration, irRange, irNoise, cameraFov,
                cameraRange, cameraNoise, chemicalRadius, odometryNoise, movingSeconds, idleSeconds);
    }

    /** How many infrared sensors there are (16). */
    public int irCount() {
        return IR_DEGREES.length;
    }

    /** Infrared sensor {@code i}'s direction, radians from the heading. */
    public double irAngle(int i) {
        return Math.toRadians(IR_DEGREES[i]);
    }

    private static void positive(String name, double value) {
        if (!(value > 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException(name + " " + value + " is not a positive finite number; it must be");
        }
    }

    private static void notNegative(String name, double value) {
        if (!(value >= 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException(name + " " + value + " is negative or not finite; it must be 0 or more");
        }
    }
}
