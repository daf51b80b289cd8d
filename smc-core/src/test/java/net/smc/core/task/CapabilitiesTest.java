package net.smc.core.task;

import net.smc.core.capability.TaskDescription;
import net.smc.core.capability.CapabilitySummary;
import net.smc.core.capability.CapabilityRequirement;
import net.smc.core.capability.CapabilityDescription;
import net.smc.core.capability.CapabilityCodec;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import net.smc.core.task.Explorer;
import net.smc.core.task.Idler;
import net.smc.core.task.Mapper;
import net.smc.core.task.TaskDescriptionException;
import org.junit.jupiter.api.Test;

/** The Capability module: the description follows the loaded tasks and the resources. */
class CapabilitiesTest {
    private final Capabilities caps = new Capabilities("uav7", Set.of("video", "motion"));

    @Test
    void description_isTheUnionOfTheLoadedTasksPlusTheResources() throws Exception {
        Explorer explorer = new Explorer();
        caps.load(explorer);
        caps.load(new Idler());
        CapabilityDescription d = caps.description();
        assertEquals("uav7", d.vehicle());
        assertEquals(List.of("motion", "video"), List.copyOf(d.resources()));
        assertEquals(List.of("Explorer", "Idler"), d.tasks().stream().map(TaskDescription::task).toList());
        assertEquals(explorer.describe(), d.task("Explorer").orElseThrow());
        assertEquals(TaskDescription.empty("Idler"), d.task("Idler").orElseThrow());
    }

    @Test
    void description_changesWhenATaskIsLoadedOrUnloaded() throws Exception {
        assertEquals(List.of(), caps.description().tasks());
        Explorer explorer = new Explorer();
        caps.load(explorer);
        assertEquals(Set.of("Explorer"), caps.description().taskNames());
        assertSame(explorer, caps.unload("Explorer").orElseThrow());
        assertEquals(Set.of(), caps.description().taskNames());
        assertTrue(caps.unload("Explorer").isEmpty());
    }

    @Test
    void description_changesWhenAResourceComesOrGoes() {
        assertTrue(caps.addResource("infrared"));
        assertFalse(caps.addResource("infrared"));
        assertTrue(caps.description().resources().contains("infrared"));
        assertTrue(caps.removeResource("video"));
        assertEquals(Set.of("infrared", "motion"), caps.summary().resources());
    }

    @Test
    void summary_matchesTheFullDescription() throws Exception {
        caps.load(new Explorer());
        caps.load(new Idler());
        CapabilitySummary summary = caps.summary();
        assertTrue(summary.matches(caps.description()));
        assertEquals(Set.of("Explorer", "Idler"), summary.tasks());
        assertEquals(caps.description().summary(), summary);
    }

    @Test
    void summary_ofAnOlderDescription_doesNotMatchOnceATaskIsLoaded() throws Exception {
        CapabilitySummary before = caps.summary();
        caps.load(new Explorer());
        assertFalse(before.matches(caps.description()));
    }

    @Test
    void load_refusesATaskThatCannotBeDescribed() {
        TaskDescriptionException e = assertThrows(TaskDescriptionException.class, () -> caps.load(new Mapper()));
        assertTrue(e.getMessage().startsWith("task Mapper implements SurveyorI, whose @TaskInterface names 'Surveyor'"),
                e.getMessage());
        assertEquals(List.of(), caps.tasks());
    }

    @Test
    void load_refusesASecondTaskOfTheSameName() throws Exception {
        caps.load(new Explorer());
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> caps.load(new Explorer()));
        assertEquals("vehicle uav7 already has a task named 'Explorer'; unload it first (a vehicle has one task per name)",
                e.getMessage());
    }

    @Test
    void load_ofTheSameTaskAgain_isHarmless() throws Exception {
        Explorer explorer = new Explorer();
        caps.load(explorer);
        caps.load(explorer);
        assertEquals(List.of(explorer), caps.tasks());
        assertSame(explorer, caps.task("Explorer").orElseThrow());
    }

    @Test
    void addResource_refusesABlankName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> caps.addResource(" "));
        assertEquals("a resource name must not be blank", e.getMessage());
    }

    @Test
    void satisfies_checksResourcesAndTasks() throws Exception {
        CapabilityRequirement surveyor = CapabilityRequirement.of(Set.of("motion", "video"), Set.of("Explorer"));
        assertFalse(caps.satisfies(surveyor));
        caps.load(new Explorer());
        assertTrue(caps.satisfies(surveyor));
        assertTrue(caps.description().satisfies(surveyor));
        assertTrue(caps.summary().satisfies(surveyor));
    }

    @Test
    void description_encodesAndDecodesLosslessly() throws Exception {
        caps.load(new Explorer());
        caps.load(new Idler());
        CapabilityCodec codec = CapabilityCodec.STANDARD;
        assertEquals(caps.description(), codec.decodeDescription(codec.encode(caps.description())));
        assertEquals(caps.summary(), codec.decodeSummary(codec.encode(caps.summary())));
    }
}
