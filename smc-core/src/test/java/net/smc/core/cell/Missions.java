package net.smc.core.cell;

import java.nio.file.Path;

import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.policy.api.PolicyRepository;

/** The shipped missions and policy repository, for the team tests. */
public final class Missions {
    public static final PolicyRepository REPOSITORY =
            new PolicyRepository(Path.of(System.getProperty("smc.repo.dir", "../policies")));
    private static final Path MISSIONS = Path.of(System.getProperty("smc.project.dir", "../")).resolve("missions");
    private static Mission distributed;
    private static Mission centralised;

    private Missions() {
    }

    /** missions/reconnaissance.instance.xml: comTimeout 500 ms, failureTimeout 3000 ms, one backup. */
    public static synchronized Mission reconnaissance() {
        if (distributed == null) {
            distributed = load("reconnaissance.instance.xml");
        }
        return distributed;
    }

    /** The same mission under the centralised scheme. */
    public static synchronized Mission centralised() {
        if (centralised == null) {
            centralised = load("reconnaissance-centralised.instance.xml");
        }
        return centralised;
    }

    private static Mission load(String file) {
        try {
            return new MissionLoader(REPOSITORY).load(MISSIONS.resolve(file));
        } catch (Exception e) {
            throw new IllegalStateException("cannot load " + file + ": " + e.getMessage(), e);
        }
    }
}
