package net.smc.core.cell;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The status view as JSON: its field names, and reading back what was written. */
class CellViewJsonTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    private static CellView commander() {
        Map<String, List<String>> children = new LinkedHashMap<>();
        children.put("a1", List.of("aggregator#0"));
        children.put("s\"1\\", List.of("surveyor#0", "surveyor#1"));
        Map<String, Integer> counts = new LinkedHashMap<>();
        counts.put("aggregator", 1);
        counts.put("surveyor", 2);
        return new CellView("cdr", "HouseSurvey", "[HouseSurvey|0|0]", 3, "cdr", true, null, false,
                List.of("commander#0"), children, MissionState.RUNNING, counts, 1_767_225_600_000L);
    }

    @Test
    void toJson_writesTheDocumentedFieldsInOrder() throws Exception {
        JsonNode tree = JSON.readTree(commander().toJson());
        List<String> names = new ArrayList<>();
        tree.fieldNames().forEachRemaining(names::add);
        assertEquals(List.of("vehicle", "mission", "identity", "epoch", "commander", "acting", "parent", "suspended",
                "roles", "children", "missionState", "counts", "time"), names);
        assertEquals("RUNNING", tree.get("missionState").asText());
        assertEquals(1_767_225_600_000L, tree.get("time").asLong());
        assertTrue(tree.get("parent").isNull());
        assertEquals("surveyor#1", tree.get("children").get("s\"1\\").get(1).asText());
    }

    @Test
    void fromJson_readsBackWhatToJsonWrote() {
        CellView view = commander();
        assertEquals(view, CellView.fromJson(view.toJson()));
    }

    @Test
    void fromJson_readsBackAViewWithoutRolesOrState() {
        CellView loose = new CellView("s9", "HouseSurvey", null, 0, null, false, null, true, List.of(), Map.of(),
                null, Map.of(), 5);
        assertEquals(loose, CellView.fromJson(loose.toJson()));
    }

    @Test
    void fromJson_rejectsAnErrorObject() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CellView.fromJson("{\"error\":\"status view failed\",\"exception\":\"x\"}"));
        assertTrue(e.getMessage().startsWith("not a status view"), e.getMessage());
    }

    @Test
    void fromJson_rejectsText_thatIsNotJson() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CellView.fromJson("up: cdr"));
        assertTrue(e.getMessage().startsWith("not a status view: "), e.getMessage());
    }
}
