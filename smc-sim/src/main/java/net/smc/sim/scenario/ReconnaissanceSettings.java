package net.smc.sim.scenario;

import java.util.Objects;

import net.smc.sim.render.GifRecorder;
import net.smc.sim.team.TeamSimulation;

/**
 * How to run a {@link ReconnaissanceScenario}: the seed, the network's extra loss, the time limit,
 * the security, the film, when the failing robot's battery dies and the coverage goal.
 *
 * @param seed          fixes every random draw of the run
 * @param loss          probability that the network loses a datagram, on top of the radio, 0 to below 1
 * @param limitMillis   mission time after which the run gives up, ms
 * @param security      how cells authenticate
 * @param film          settings of the GIF film, or null for none
 * @param failureMillis when the failing robot's battery dies, ms of mission time (negative: never)
 * @param coverageGoal  the share of the free floor the hazard map must know, 0 to 1
 */
public record ReconnaissanceSettings(long seed, double loss, long limitMillis, TeamSimulation.Security security,
                                     GifRecorder.Settings film, long failureMillis, double coverageGoal) {
    public ReconnaissanceSettings {
        if (!(loss >= 0 && loss < 1)) {
            throw new IllegalArgumentException("loss " + loss + " is out of range; it must be 0 or more and below 1");
        }
        if (limitMillis <= 0) {
            throw new IllegalArgumentException("limit " + limitMillis + " ms must be positive");
        }
        if (!(coverageGoal > 0 && coverageGoal <= 1)) {
            throw new IllegalArgumentException("coverage goal " + coverageGoal + " is out of range; it must be above 0 and at most 1");
        }
        Objects.requireNonNull(security, "security");
    }

    /** No extra loss, 900 s of mission time, ideal authentication, no film, the battery dies at 70 s, 90% of the floor. */
    public static ReconnaissanceSettings of(long seed) {
        return new ReconnaissanceSettings(seed, 0, 900_000, TeamSimulation.Security.IDEAL, null, 70_000, 0.9);
    }

    public ReconnaissanceSettings withLoss(double p) {
        return new ReconnaissanceSettings(seed, p, limitMillis, security, film, failureMillis, coverageGoal);
    }

    public ReconnaissanceSettings withLimit(long millis) {
        return new ReconnaissanceSettings(seed, loss, millis, security, film, failureMillis, coverageGoal);
    }

    public ReconnaissanceSettings withFilm(GifRecorder.Settings f) {
        return new ReconnaissanceSettings(seed, loss, limitMillis, security, f, failureMillis, coverageGoal);
    }

    public ReconnaissanceSettings withSecurity(TeamSimulation.Security s) {
        return new ReconnaissanceSettings(seed, loss, limitMillis, s, film, failureMillis, coverageGoal);
    }

    public ReconnaissanceSettings withFailureAt(long millis) {
        return new ReconnaissanceSettings(seed, loss, limitMillis, security, film, millis, coverageGoal);
    }
}
