/**
 * Team configuration: which vehicles hold which roles of a {@link net.smc.core.mission.Mission},
 * given their capability summaries. The paper's section II-A asks for a team that starts with the
 * minimal configuration, grows towards the reasonably-optimal one as vehicles join and contracts
 * when they leave; a plan is a pure function of the mission and the vehicles, so the same call
 * answers all three.
 *
 * <p>Start at {@link net.smc.core.team.TeamPlanner}; its answer is a
 * {@link net.smc.core.team.TeamConfiguration} of {@link net.smc.core.team.Assignment}s. Inside:
 * {@code RoleTable} and {@code Fleet} turn the mission and vehicles into arrays and bitsets,
 * {@code Board} holds the working state with exact undo, {@code MinimalSearch} fills the minimal
 * configuration (exact search, greedy first path), and {@code Growth} grows it.
 *
 * <p>The JMH benchmark {@code TeamPlannerBench} (source set {@code jmh}) measures a plan of 1,000
 * vehicles for 100 roles: {@code ./gradlew :smc-core:jmh -PjmhArgs="TeamPlannerBench"}.
 */
package net.smc.core.team;
