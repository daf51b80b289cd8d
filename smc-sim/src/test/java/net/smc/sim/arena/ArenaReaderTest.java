package net.smc.sim.arena;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import net.smc.sim.world.Worlds;
import org.junit.jupiter.api.Test;

class ArenaReaderTest {
    private static final Path FILE = Path.of("bad.xml");

    private static List<ArenaError> errors(String text) {
        return assertThrows(ArenaException.class, () -> ArenaReader.parse(FILE, text)).errors();
    }

    private static String only(String text) {
        List<ArenaError> errors = errors(text);
        assertEquals(1, errors.size(), errors.toString());
        return errors.get(0).toString();
    }

    @Test
    void rescue_loadsWithTheHazardOnTheStraightLineFromStartToSoldier() throws Exception {
        Arena rescue = ArenaReader.read(Worlds.worldFile("rescue.xml"));
        Arena.Start start = rescue.start("r1").orElseThrow();
        Arena.Target soldier = rescue.targets().get(0);
        Arena.Hazard hazard = rescue.hazards().get(0);
        assertEquals("soldier", soldier.kind());
        assertTrue(hazard.disables());
        // distance from the hazard's centre to the segment start-soldier
        double dx = soldier.x() - start.x();
        double dy = soldier.y() - start.y();
        double t = ((hazard.x() - start.x()) * dx + (hazard.y() - start.y()) * dy) / (dx * dx + dy * dy);
        assertTrue(t > 0 && t < 1, "the hazard lies between start and soldier");
        double off = Math.hypot(start.x() + t * dx - hazard.x(), start.y() + t * dy - hazard.y());
        assertTrue(off < hazard.effect(), "the straight line passes " + off + " m from the hazard");
    }

    @Test
    void house_loadsWithRoomsDoorsHazardsAndEightStarts() throws Exception {
        Arena house = ArenaReader.read(Worlds.worldFile("house.xml"));
        assertTrue(house.hazards().size() >= 3);
        assertTrue(house.starts().size() >= 8);
        assertTrue(house.doors().size() >= 6);
        assertTrue(house.doors().stream().anyMatch(d -> !d.open()));
        assertTrue(house.walls().size() >= 10);
    }

    @Test
    void notWellFormed_isReportedAtTheParsersPosition() {
        String error = only("<world name='x' width='4' height='4'>\n  <start id='s' x='1' y='1'>\n</world>");
        assertTrue(error.startsWith("bad.xml:3:"), error);
        assertTrue(error.contains("not well-formed XML"), error);
        assertTrue(error.endsWith("a world file must be well-formed XML"), error);
    }

    @Test
    void doctype_isRefusedAtItsPosition() {
        String error = only("<?xml version='1.0'?>\n<!DOCTYPE world [<!ENTITY x SYSTEM 'file:///etc/passwd'>]>\n"
                + "<world name='&x;' width='4' height='4'/>");
        assertEquals("bad.xml:2:1: a DOCTYPE declaration is not allowed; a world file has no DTD (its format is "
                + "missions/worlds/world.xsd), so remove <!DOCTYPE ...>", error);
    }

    @Test
    void overlongAttribute_isRefusedWithItsElementAndLimit() {
        String error = only("<world name='" + "x".repeat(5000) + "' width='4' height='4'>\n</world>");
        assertEquals("bad.xml:1:1: <world>: attribute 'name' has 5000 characters; an attribute value may have at most "
                + "4096", error);
    }

    @Test
    void oversizedText_isRefusedUnparsed() {
        String text = "<world name='x' width='4' height='4'>" + " ".repeat(1024 * 1024) + "</world>";
        assertEquals("bad.xml:1:1: the text has " + text.length() + " characters; a world file may have at most "
                + "1048576", only(text));
    }

    @Test
    void unknownElement_namesItsPlaceAndTheAllowedOnes() {
        String error = only("<world name='x' width='4' height='4'>\n<start id='s' x='1' y='1'/>\n  <tree x='1'/>\n</world>");
        assertEquals("bad.xml:3:3: <tree>: unexpected element in <world>; expected <wall>, <door>, <box>, "
                + "<cylinder>, <hazard>, <target>, <station> or <start>", error);
    }

    @Test
    void missingAttribute_isReported() {
        String error = only("<world name='x' width='4' height='4'>\n<start id='s' x='1' y='1'/>\n<wall x1='1' y1='1' y2='3'/>\n</world>");
        assertEquals("bad.xml:3:1: <wall>: missing attribute 'x2'; <wall> needs x1, y1, x2 and y2", error);
    }

    @Test
    void notANumber_isReported() {
        String error = only("<world name='x' width='4' height='4'>\n<start id='s' x='one' y='1'/>\n</world>");
        assertEquals("bad.xml:2:1: <start>: attribute 'x' is 'one'; it must be a finite decimal number", error);
    }

    @Test
    void coordinateOutsideTheArena_isReported() {
        String error = only("<world name='x' width='4' height='4'>\n<start id='s' x='1' y='1'/>\n<hazard id='h' x='5' y='1' effect='1'/>\n</world>");
        assertEquals("bad.xml:3:1: <hazard>: x 5.0 lies outside the arena; it must be within 0 to 4.0", error);
    }

    @Test
    void duplicateId_pointsAtTheFirstUse() {
        String error = only("<world name='x' width='4' height='4'>\n<start id='s' x='1' y='1'/>\n<start id='s' x='3' y='3'/>\n</world>");
        assertEquals("bad.xml:3:1: <start>: id 's' is used already by <start> at line 2; ids must be unique in a world file", error);
    }

    @Test
    void hazardEffectInsideItsBody_isReported() {
        String error = only("<world name='x' width='4' height='4'>\n<start id='s' x='1' y='1'/>\n<hazard id='h' x='3' y='3' radius='0.5' effect='0.2'/>\n</world>");
        assertTrue(error.startsWith("bad.xml:3:1: <hazard>: effect 0.2 is less than radius 0.5; "), error);
    }

    @Test
    void startInsideAWall_isReported() {
        String error = only("<world name='x' width='4' height='4'>\n<wall x1='2' y1='0' x2='2' y2='4'/>\n<start id='s' x='2.1' y='2'/>\n</world>");
        assertTrue(error.startsWith("bad.xml:3:1: <start>: start 's' at (2.10, 2.00) is 0.05 m from a wall or obstacle; "), error);
    }

    @Test
    void wrongRoot_andMissingStart_areReported() {
        assertEquals("bad.xml:1:1: <arena>: unexpected root element; a world file's root is <world>",
                only("<arena name='x'/>"));
        assertEquals("bad.xml:1:1: <world>: no <start>; a world needs at least one start position",
                only("<world name='x' width='4' height='4'/>"));
    }

    @Test
    void everyErrorOfAFileIsListed_inFileOrder() {
        List<ArenaError> errors = errors("<world name='' width='4' height='4'>\n<start id='s' x='1' y='1' colour='red'/>\n"
                + "<door id='d' x1='1' y1='1' x2='1' y2='1' open='yes'/>\n</world>");
        assertEquals(4, errors.size(), errors.toString());
        for (int i = 1; i < errors.size(); i++) {
            assertFalse(errors.get(i).line() < errors.get(i - 1).line(), errors.toString());
        }
        assertTrue(errors.stream().anyMatch(e -> e.toString().contains("1:1: <world>: empty attribute 'name'")), errors.toString());
        assertTrue(errors.stream().anyMatch(e -> e.toString().contains("unexpected attribute 'colour'")), errors.toString());
        assertTrue(errors.stream().anyMatch(e -> e.toString().contains("'open' is 'yes'; it must be true or false")), errors.toString());
        assertTrue(errors.stream().anyMatch(e -> e.toString().contains("must have a length")), errors.toString());
    }
}
