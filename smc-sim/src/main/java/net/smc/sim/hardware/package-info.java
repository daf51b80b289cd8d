/**
 * The hardware interface between tasks and a robot's devices: drive, odometry, infrared
 * proximity sensors, camera, chemical sensor, battery and clock-free control ticks. A task
 * written against {@link net.smc.sim.hardware.RobotHardware} does not know whether the devices are
 * simulated ({@code net.smc.sim.robot}) or real.
 *
 * <p>Units: metres, seconds, radians (counter-clockwise, 0 along +x), metres per second. All calls
 * are made on the owning cell's thread.
 */
package net.smc.sim.hardware;
