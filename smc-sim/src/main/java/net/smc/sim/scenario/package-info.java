/**
 * The paper's scenarios run by cells and policies in the world. {@link
 * net.smc.sim.scenario.RescueScenario} is the wounded-soldier rescue of section IV-C: a team
 * simulation with the rescue arena, whose steps (i)-(vii) the policies of {@code policies/}
 * decide; it records a timeline, trajectories and a film of the run.
 */
package net.smc.sim.scenario;
