/**
 * The set-up time experiment of the paper's section V (Fig. 8): {@link net.smc.sim.experiment.MissionGenerator}
 * writes missions of any number of roles in a management tree of depth 4, {@link net.smc.sim.experiment.SetupTimeRun}
 * runs one team on the simulated network ({@link net.smc.sim.experiment.RadioNetwork}: an ad-hoc
 * radio, or a switched LAN) with each cell's CPU charged to its own virtual clock and each datagram
 * carried as long as the real security layer makes it, handshakes included
 * ({@link net.smc.sim.experiment.CpuCharge}, costs from {@link net.smc.sim.experiment.Calibration}),
 * and measures the time from the commander's start until every role is started;
 * {@link net.smc.sim.experiment.UdpSetupTimeRun} runs the same team on loopback UDP.
 */
package net.smc.sim.experiment;
