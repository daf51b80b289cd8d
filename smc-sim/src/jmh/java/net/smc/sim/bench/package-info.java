/**
 * JMH benchmarks of the simulator: the cost of a world step per robot with every sensor read
 * ({@link net.smc.sim.bench.WorldStepBenchmark}), and how whole teams of cells scale
 * ({@link net.smc.sim.bench.ScaledTeam}: one vehicle per role of a generated mission, a management
 * tree of depth 4): formation time versus team size ({@link net.smc.sim.bench.FormationBenchmark}),
 * simulated seconds per wall second and steady-state traffic of idle teams
 * ({@link net.smc.sim.bench.SimulationSpeedBenchmark}); plus two plain mains,
 * {@link net.smc.sim.bench.CellMemoryReport} (heap per cell) and
 * {@link net.smc.sim.bench.TeamScaleReport} (one run per size, traffic by message type).
 *
 * <pre>
 * ./gradlew :smc-sim:jmh -PjmhArgs='FormationBenchmark -p vehicles=10,100,1000'
 * ./gradlew :smc-sim:jmh -PjmhMain=net.smc.sim.bench.CellMemoryReport -PjmhArgs='100 1000'
 * </pre>
 */
package net.smc.sim.bench;
