package net.smc.sim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

import net.smc.core.message.DecodeResult;
import net.smc.core.message.MessageDecoder;
import net.smc.core.message.MessageType;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.DropReason;
import net.smc.core.transport.sim.NetworkObserver;
import net.smc.sim.render.Timeline;
import net.smc.sim.team.TeamSimulation;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The rescue is assembled when the soldier calls for help, as the paper's steps (ii) and (iii)
 * go: the commander's policy holds its recruiting until the distress arrives, so no discovery or
 * assignment traffic is on the air before it, and the timeline shows (ii) before (iii).
 */
class RescueAssemblyTest {
    private static final Path PROJECT = Path.of(System.getProperty("smc.project.dir", ".."));
    private static final Set<MessageType> ASSEMBLY = EnumSet.of(MessageType.DISCOVERY, MessageType.DISCOVERY_REPLY,
            MessageType.CAPABILITY_REQUEST, MessageType.CAPABILITY_REPLY, MessageType.ROLE_ASSIGNMENT,
            MessageType.ASSIGNMENT_RESPONSE, MessageType.POLICY_REQUEST, MessageType.POLICY_REPLY);

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12})
    void noDiscoveryOrAssignmentBeforeTheDistressCall(long seed) throws Exception {
        RescueScenario s = RescueScenario.load(PROJECT, RescueScenario.Settings.of(seed)
                .withSecurity(TeamSimulation.Security.IDEAL), row -> { });
        TeamSimulation team = (TeamSimulation) s.team();   // the simulated transport: one virtual clock
        // every discovery or assignment datagram copy on the air: when it was seen, and what it was
        List<String> assembly = new ArrayList<>();
        long[] first = {Long.MAX_VALUE};
        MessageDecoder decoder = new MessageDecoder(team::nowMillis);
        team.network().addObserver(new NetworkObserver() {
            @Override
            public void delivered(long atMillis, Address from, Address to, byte[] data) {
                seen(atMillis, from, data);
            }

            @Override
            public void dropped(long atMillis, Address from, Address to, DropReason reason, byte[] data) {
                seen(atMillis, from, data);
            }

            /**
             * An ideally authenticated datagram is a counter, the envelope, and a tag of 8 bytes
             * each way; the counter's high bits are the mission time it was sent at.
             */
            private void seen(long atMillis, Address from, byte[] data) {
                long sent = ByteBuffer.wrap(data).getLong(0) >> 20;
                byte[] envelope = Arrays.copyOfRange(data, 8, data.length - 8);
                // the transport names the sender (the header leaves it out but for discoveries and their replies)
                String sender = team.vehicleAt(from).orElse(null);
                if (decoder.decode(sender, envelope, 0, envelope.length) instanceof DecodeResult.Decoded d && ASSEMBLY.contains(d.envelope().type())) {
                    assembly.add("sent " + sent + " ms: " + d.envelope().type() + " from " + d.envelope().sender());
                    first[0] = Math.min(first[0], sent);
                }
            }
        });
        RescueScenario.Outcome o = s.run();
        assertTrue(o.succeeded(), o.reason());
        long distress = s.distressHeardMillis();
        assertTrue(distress >= 0, "the commander heard the distress");
        assertTrue(!assembly.isEmpty(), "the team was assembled over the air");
        assertTrue(first[0] >= distress, () -> "seed " + seed + ": distress heard at " + distress
                + " ms, but assembly traffic at " + assembly.subList(0, Math.min(5, assembly.size())));
        for (String line : team.trace()) {
            String[] f = line.trim().split("\\s+", 4);
            if (f[1].equals("cdr") && f[2].equals("DISCOVERING")) {
                assertTrue(Long.parseLong(f[0]) >= distress, "the commander discovers only after the distress: " + line);
            }
        }
        List<Timeline.Row> rows = s.timeline().rows();
        int ii = -1;
        int iii = -1;
        for (int i = 0; i < rows.size(); i++) {
            if (ii < 0 && rows.get(i).step().equals("ii")) {
                ii = i;
            }
            if (iii < 0 && rows.get(i).step().equals("iii")) {
                iii = i;
            }
        }
        assertTrue(ii >= 0 && iii > ii, "(ii) at row " + ii + ", (iii) at row " + iii);
        assertTrue(rows.get(iii).timeMillis() >= distress);
        assertEquals("cdr", rows.stream().filter(r -> r.detail().startsWith("distress from")).findFirst()
                .orElseThrow().vehicle());
    }
}
