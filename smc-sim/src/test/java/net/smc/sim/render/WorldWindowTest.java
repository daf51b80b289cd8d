package net.smc.sim.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class WorldWindowTest {

    @Test
    void headless_open_saysThereIsNoDisplay() {
        assertFalse(WorldWindow.displayAvailable(), "the tests run with java.awt.headless=true");
        NoDisplayException e = assertThrows(NoDisplayException.class,
                () -> WorldWindow.open("rescue", 800, 600, ViewControls.defaults()));
        assertEquals("no display; running headless", e.getMessage());
    }

    @Test
    void tooSmallWindow_isRefusedBeforeLookingForADisplay() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> WorldWindow.open("rescue", 10, 600, ViewControls.defaults()));
        assertEquals("window of 10 x 600 px is too small; it must be at least 64 x 64", e.getMessage());
    }
}
