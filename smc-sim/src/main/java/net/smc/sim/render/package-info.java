/**
 * Pictures of a simulated world: {@link net.smc.sim.render.WorldPainter} (the place to start)
 * draws a {@link net.smc.sim.world.SimWorld} and a {@link net.smc.sim.render.Scene} (roles,
 * trajectories, marks, overlays, caption) onto any {@code Graphics2D}; around it sit the recorders
 * that feed it or keep what it drew: {@link net.smc.sim.render.TrajectoryRecorder},
 * {@link net.smc.sim.render.GifRecorder}, the CSV {@link net.smc.sim.render.Timeline}, and the live
 * Swing {@link net.smc.sim.render.WorldWindow} with its pacing ({@link net.smc.sim.render.ViewControls},
 * {@link net.smc.sim.render.PacedLoop}).
 *
 * <pre>{@code
 * TrajectoryRecorder tracks = new TrajectoryRecorder(5);       // a point every 5 steps
 * world.addListener(tracks);
 * Scene scene = new Scene("Rescue (Fig. 7)").trajectories(tracks).roles(Map.of("r1", "surveyor")::get);
 * scheduler.runFor(60_000);
 * ImageIO.write(new WorldPainter().render(world, scene, 1200, 860), "png", file);
 * }</pre>
 */
package net.smc.sim.render;
