package net.smc.sim.scenario;

import java.util.List;

/**
 * How a {@link ReconnaissanceScenario} run ended: whether the goal was met, the coverage and
 * hazards of the aggregator's map, and the standings the team passed through.
 *
 * @param succeeded      whether the goal was met
 * @param reason         what was achieved, or why not
 * @param missionMillis  mission time at the end, ms
 * @param coverage       the share of the free floor on the aggregator's map at the end
 * @param coverageMillis when the map first reached the coverage goal, or -1
 * @param hazardsFound   the house's hazards on the aggregator's map, by id
 * @param standings      the standings the team passed through, in order, each once per stretch
 *                       ("forming", "minimal", "grown", "optimal")
 */
public record ReconnaissanceOutcome(boolean succeeded, String reason, long missionMillis, double coverage, long coverageMillis,
                                    List<String> hazardsFound, List<String> standings) {
}
