package net.smc.sim.scenario;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionException;
import net.smc.core.mission.MissionLoader;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.arena.Arena;
import net.smc.sim.arena.ArenaException;
import net.smc.sim.arena.ArenaReader;

/**
 * What a scenario reads from the project's folder: the policy repository {@code policies/}, a
 * mission instance under {@code missions/} and a world file under {@code missions/worlds/}.
 *
 * @param repository the policy repository
 * @param mission    the mission instance, checked against its class
 * @param arena      the world
 */
record ScenarioFiles(PolicyRepository repository, Mission mission, Arena arena) {

    /**
     * Reads {@code missions/<instance>} and {@code missions/worlds/<world>} of {@code projectDir}.
     *
     * @throws IOException      when a file is missing (naming it) or cannot be read
     * @throws MissionException when the mission is invalid (every error listed)
     * @throws ArenaException   when the world file is invalid
     */
    static ScenarioFiles load(Path projectDir, String instance, String world)
            throws IOException, MissionException, ArenaException {
        Path policies = projectDir.resolve("policies");
        Path instanceFile = projectDir.resolve("missions").resolve(instance);
        Path worldFile = projectDir.resolve("missions/worlds").resolve(world);
        for (Path p : List.of(policies, instanceFile, worldFile)) {
            if (!Files.exists(p)) {
                throw new IOException(p + " not found; run from the project's folder (it needs policies/ and missions/)");
            }
        }
        PolicyRepository repository = new PolicyRepository(policies);
        Mission mission = new MissionLoader(repository).load(instanceFile);
        return new ScenarioFiles(repository, mission, ArenaReader.read(worldFile));
    }
}
