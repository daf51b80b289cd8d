/**
 * Tasks written against the hardware interface ({@link net.smc.sim.hardware.RobotHardware}), for
 * the paper's reconnaissance and rescue missions: {@link net.smc.sim.task.Explorer},
 * {@link net.smc.sim.task.Navigator}, {@link net.smc.sim.task.HazardDetector},
 * {@link net.smc.sim.task.Aggregator}, {@link net.smc.sim.task.Relay}, and the soldier's
 * {@link net.smc.sim.task.Beacon} and the rescuer's {@link net.smc.sim.task.Assist}. Start at
 * {@link net.smc.sim.task.TaskCatalog}, which names them, describes them (the paper's Table V) and
 * makes them for one robot:
 *
 * <pre>{@code
 * TaskCatalog catalog = TaskCatalog.standard();
 * TaskDescription d = catalog.describe("Navigator");         // goTo:y:, avoid:y:radius: ...; arrived, blocked
 * Task nav = catalog.create("Navigator", new TaskContext(robot, map));
 * nav.bind(cell);                                            // root/task/Navigator, root/event/arrived ...
 * nav.start();                                               // its control loop now runs every world step
 * }</pre>
 *
 * <p>Each task does its work in a {@link net.smc.sim.hardware.ControlLoop} registered with its
 * robot while it runs. Tasks whose state is worth handing to a replacement implement
 * {@link net.smc.sim.task.Handover}.
 */
package net.smc.sim.task;
