/**
 * Simulated Koala-like robots ({@link net.smc.sim.robot.SimRobot}, built to a
 * {@link net.smc.sim.robot.KoalaSpec}): the {@link net.smc.sim.hardware.RobotHardware} of a robot
 * in a {@link net.smc.sim.world.SimWorld}, with a differential drive, wheel odometry, 16 infrared
 * sensors, a forward camera, a chemical sensor, a battery and a radio. A robot sees the world only
 * through a {@link net.smc.sim.robot.RobotGround}, which the world implements: the world makes and
 * steps robots, and this package does not depend on it.
 */
package net.smc.sim.robot;
