package net.smc.policy.stdlib;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import net.smc.policy.PolicyEngine;
import org.junit.jupiter.api.Test;

class StandardObjectsTest {

    @Test
    void everyStandardObject_isLoadableByItsName() {
        List<String> lines = new ArrayList<>();
        PolicyEngine cell = PolicyEngine.builder().output(lines::add).build();
        for (String name : StandardObjects.classes().keySet()) {
            cell.run("t.p2", "root print: (root load: \"" + name + "\")");
        }
        assertEquals(StandardObjects.classes().size(), lines.size());
        lines.forEach(line -> assertEquals("<Factory>", line));
    }

    @Test
    void xml_withAnExternalEntity_isRefusedBeforeAnythingIsRead() {
        List<String> errors = new ArrayList<>();
        PolicyEngine cell = PolicyEngine.builder().errors(d -> errors.add(d.message())).build();
        cell.run("t.p2", "\"<!DOCTYPE a [<!ENTITY e SYSTEM 'file:///etc/hostname'>]><a>&e;</a>\" asXML");
        assertEquals(List.of("not XML: a DOCTYPE is not allowed"), errors);
    }
}
