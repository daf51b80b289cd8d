package net.smc.sim.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ViewControlsTest {

    @Test
    void space_pausesAndResumes() {
        ViewControls controls = ViewControls.defaults();
        assertTrue(controls.key(' '));
        assertTrue(controls.paused());
        controls.key(' ');
        assertFalse(controls.paused());
    }

    @Test
    void plusAndMinus_stepTheSpeed_withinTheLadder() {
        ViewControls controls = ViewControls.defaults();
        assertEquals(1, controls.speed());
        controls.key('+');
        assertEquals(2, controls.speed());
        controls.key('=');
        assertEquals(4, controls.speed());
        controls.key('-');
        controls.key('-');
        controls.key('-');
        assertEquals(0.5, controls.speed());
        for (int i = 0; i < 20; i++) {
            controls.key('-');
        }
        assertEquals(0.125, controls.speed());
        for (int i = 0; i < 20; i++) {
            controls.key('+');
        }
        assertEquals(64, controls.speed());
    }

    @Test
    void letters_toggleTheOverlays() {
        ViewControls controls = ViewControls.defaults();
        controls.key('r');
        assertTrue(controls.overlays().irRays());
        controls.key('c');
        assertTrue(controls.overlays().cameraCones());
        controls.key('L');
        assertTrue(controls.overlays().radioLinks());
        controls.key('r');
        assertFalse(controls.overlays().irRays());
        controls.key('t');
        assertFalse(controls.overlays().trajectories());
    }

    @Test
    void otherKeys_changeNothing() {
        ViewControls controls = ViewControls.defaults();
        Overlays before = controls.overlays();
        assertFalse(controls.key('x'));
        assertEquals(before, controls.overlays());
        assertEquals(1, controls.speed());
        assertFalse(controls.paused());
    }

    @Test
    void startSpeed_snapsToTheNearestStep_andStatusSaysIt() {
        ViewControls controls = new ViewControls(3.5, Overlays.defaults());
        assertEquals(4, controls.speed());
        controls.key(' ');
        assertTrue(controls.status().startsWith("4x, paused"), controls.status());
        assertTrue(new ViewControls(0.2, Overlays.defaults()).status().startsWith("1/4x"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new ViewControls(0, Overlays.defaults()));
        assertTrue(e.getMessage().contains("view speed 0.0"), e.getMessage());
    }
}
