package net.smc.core.capability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** Role matching's question: does a vehicle provide these resources and tasks, and if not, what does it lack? */
class CapabilityRequirementTest {
    private static final TaskDescription EXPLORER = new TaskDescription("Explorer",
            List.of(new OperationDescription("moveTo", List.of("double", "double"))), List.of());
    private static final CapabilityDescription UAV = CapabilityDescription.of("uav1", Set.of("motion", "video"),
            List.of(EXPLORER, TaskDescription.empty("Relay")));

    @Test
    void isMetBy_whenEveryResourceAndTaskIsThere() {
        CapabilityRequirement r = CapabilityRequirement.of(Set.of("video"), Set.of("Explorer", "Relay"));
        assertTrue(r.isMetBy(UAV));
        assertTrue(r.isMetBy(UAV.summary()));
    }

    @Test
    void isNotMetBy_whenAResourceIsMissing() {
        CapabilityRequirement r = CapabilityRequirement.of(Set.of("video", "chemical"), Set.of());
        assertFalse(r.isMetBy(UAV));
        assertFalse(r.isMetBy(UAV.summary()));
    }

    @Test
    void isNotMetBy_whenATaskIsMissing() {
        CapabilityRequirement r = CapabilityRequirement.of(Set.of(), Set.of("Surveyor"));
        assertFalse(r.isMetBy(UAV));
        assertFalse(r.isMetBy(UAV.summary()));
    }

    /**
     * A description is matched without building its summary: over every requirement drawn from a
     * few resources and tasks (some the vehicle has, some not), the answer is the summary's.
     */
    @Test
    void isMetBy_aDescription_answersAsItsSummaryForEveryRequirement() {
        List<String> resources = List.of("motion", "video", "chemical");
        List<String> tasks = List.of("Explorer", "Relay", "Surveyor");
        int met = 0;
        for (int rm = 0; rm < 1 << resources.size(); rm++) {
            for (int tm = 0; tm < 1 << tasks.size(); tm++) {
                Set<String> rs = new java.util.HashSet<>();
                Set<String> ts = new java.util.HashSet<>();
                for (int i = 0; i < 3; i++) {
                    if ((rm >> i & 1) != 0) {
                        rs.add(resources.get(i));
                    }
                    if ((tm >> i & 1) != 0) {
                        ts.add(tasks.get(i));
                    }
                }
                CapabilityRequirement r = CapabilityRequirement.of(rs, ts);
                assertEquals(r.isMetBy(UAV.summary()), r.isMetBy(UAV), r.describe());
                met += r.isMetBy(UAV) ? 1 : 0;
            }
        }
        assertEquals(16, met, "requirements within motion, video, Explorer and Relay");
    }

    @Test
    void hasTask_namesExactlyTheTasksOfTheDescription() {
        assertTrue(UAV.hasTask("Explorer"));
        assertTrue(UAV.hasTask("Relay"));
        assertFalse(UAV.hasTask("Surveyor"));
        assertFalse(UAV.hasTask("explorer"));
    }

    @Test
    void theEmptyRequirement_isMetByAnyVehicle() {
        assertTrue(CapabilityRequirement.none().isMetBy(CapabilityDescription.of("bare", Set.of(), List.of())));
        assertEquals("nothing", CapabilityRequirement.none().describe());
    }

    @Test
    void missingFrom_listsExactlyWhatIsLacking() {
        CapabilityRequirement r = CapabilityRequirement.of(Set.of("video", "infrared", "chemical"), Set.of("Explorer", "Surveyor"));
        CapabilityRequirement missing = r.missingFrom(UAV);
        assertEquals(CapabilityRequirement.of(Set.of("chemical", "infrared"), Set.of("Surveyor")), missing);
        assertEquals("resources [chemical, infrared] and tasks [Surveyor]", missing.describe());
        assertEquals(missing, r.missingFrom(UAV.summary()));
    }

    @Test
    void missingFrom_isEmptyWhenMet() {
        CapabilityRequirement r = CapabilityRequirement.of(Set.of("motion"), Set.of("Relay"));
        assertTrue(r.missingFrom(UAV).isEmpty());
    }

    @Test
    void describe_namesOnlyTheKindsThatAreMissing() {
        assertEquals("resources [sonar]", CapabilityRequirement.of(Set.of("sonar"), Set.of()).describe());
        assertEquals("tasks [Relay]", CapabilityRequirement.of(Set.of(), Set.of("Relay")).describe());
    }

    @Test
    void requirement_isACopySortedAndUnchangeable() {
        java.util.HashSet<String> resources = new java.util.HashSet<>(Set.of("video", "audio"));
        CapabilityRequirement r = CapabilityRequirement.of(resources, Set.of());
        resources.add("sonar");
        assertEquals(List.of("audio", "video"), List.copyOf(r.resources()));
        org.junit.jupiter.api.Assertions.assertThrows(UnsupportedOperationException.class, () -> r.resources().add("x"));
    }
}
