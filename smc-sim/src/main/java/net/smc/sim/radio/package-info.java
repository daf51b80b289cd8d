/**
 * The radio between simulated robots ({@link net.smc.sim.radio.WorldRadio}): a
 * {@link net.smc.core.transport.sim.RadioModel} for the in-memory network computed from positions,
 * range, walls and distance-dependent loss, and the robots' {@link net.smc.sim.hardware.Radio} view.
 */
package net.smc.sim.radio;
