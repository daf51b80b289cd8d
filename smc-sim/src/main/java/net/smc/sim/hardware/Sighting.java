package net.smc.sim.hardware;

/**
 * One tagged object the camera sees.
 *
 * @param tag      the object's tag ({@code soldier}, {@code hazard:h1}, a robot id ...)
 * @param kind     what it is ({@code soldier}, {@code hazard}, {@code robot}, {@code marker})
 * @param bearing  radians relative to the robot's heading, positive to the left
 * @param distance metres from the camera
 */
public record Sighting(String tag, String kind, double bearing, double distance) {
}
