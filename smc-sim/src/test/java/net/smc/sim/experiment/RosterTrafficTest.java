package net.smc.sim.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import net.smc.core.cell.Scheme;
import net.smc.core.message.DecodeResult;
import net.smc.core.message.MessageDecoder;
import net.smc.core.message.Roster;
import net.smc.core.mission.Mission;
import net.smc.core.mission.MissionLoader;
import net.smc.core.security.IdealAuthentication;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.NetworkObserver;
import net.smc.policy.api.PolicyRepository;
import net.smc.sim.team.TeamSimulation;

/**
 * The acting commander keeps its backup's roster current without sending one per change: a
 * centralised commander seats every vehicle itself, and a roster per acceptance, each naming every
 * member so far, grew with the square of the team on the commander's one radio.
 */
class RosterTrafficTest {
    private static final int ROLES = 50;

    @TempDir
    Path dir;

    @Test
    void centralisedCommander_sendsAFewRostersWhileSeatingFifty_andTheLastNamesEveryMember() throws Exception {
        GeneratedMission g = MissionGenerator.write(TreeShape.of(ROLES, 4), dir, Project.bootEvents());
        Mission mission = new MissionLoader(new PolicyRepository(g.repository())).load(g.instanceFile(Scheme.CENTRALISED));
        TeamSimulation sim = TeamSimulation.builder(mission, new PolicyRepository(g.repository()), 7)
                .vehicles(g.vehicles(0)).scheme(Scheme.CENTRALISED).link(RadioNetwork.ADHOC_80211.link()).build();
        Address commander = sim.address(GeneratedMission.COMMANDER);
        MessageDecoder decoder = new MessageDecoder(sim::nowMillis);
        List<Roster> rosters = new ArrayList<>();
        sim.network().addObserver(new NetworkObserver() {
            @Override
            public void sent(long atMillis, Address from, Address to, byte[] data) {
                if (from.equals(commander)) {
                    // the seal: a counter before the message, a tag after it; the transport names the sender
                    if (decoder.decode(GeneratedMission.COMMANDER, data, IdealAuthentication.PAYLOAD_OFFSET, data.length - IdealAuthentication.SEAL_BYTES)
                            instanceof DecodeResult.Decoded d && d.envelope().body() instanceof Roster r) {
                        rosters.add(r);
                    }
                }
            }
        });
        sim.start();
        long comTimeout = MissionGenerator.COM_TIMEOUT_MILLIS;
        sim.run(4 * comTimeout);
        assertTrue(sim.cell(GeneratedMission.COMMANDER).isActingCommander());

        long ticks = sim.nowMillis() / comTimeout;
        assertTrue(rosters.size() <= 2 * ticks + 1, rosters.size() + " rosters in " + sim.nowMillis()
                + " ms: at most one per half heartbeat period, not one per seat accepted (" + (ROLES - 1) + ")");
        Roster last = rosters.get(rosters.size() - 1);
        assertEquals(ROLES - 1, last.members().size(), "the last roster names every seat: " + last);
    }
}
