/** JMH benchmarks of the simulated world: the cost of a step per robot with every sensor read. */
package net.smc.sim.bench;
