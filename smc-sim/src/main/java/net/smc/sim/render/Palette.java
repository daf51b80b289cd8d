package net.smc.sim.render;

import java.awt.Color;

/** The colours of a picture; tests sample them. */
public final class Palette {
    public static final Color BACKGROUND = new Color(0xFFFFFF);
    public static final Color FLOOR = new Color(0xEEEAE0);
    public static final Color GRID = new Color(0xDDD8CB);
    public static final Color WALL = new Color(0x44474D);
    public static final Color DOOR_CLOSED = new Color(0x8D5A2B);
    public static final Color DOOR_OPEN = new Color(0x5E9E5A);
    public static final Color OBSTACLE = new Color(0x8C8F96);
    /** The hazard's solid cylinder: the paper's yellow. */
    public static final Color HAZARD = new Color(0xFFD400);
    /** The hazard's reach: a translucent ring around it. */
    public static final Color HAZARD_REACH = new Color(0xFF, 0xC8, 0x00, 0x50);
    public static final Color HAZARD_EDGE = new Color(0xB08900);
    public static final Color SOLDIER = new Color(0x2E6B30);
    public static final Color STATION = new Color(0x37474F);
    public static final Color MARK = new Color(0xE01010);
    /** A hazard as the team reported it. */
    public static final Color FOUND = new Color(0xD81B60);
    /** Floor a map does not know, drawn over the arena. */
    public static final Color UNMAPPED = new Color(0x50, 0x50, 0x58, 0x9C);
    /** A cell a map holds occupied. */
    public static final Color MAPPED_OBSTACLE = new Color(0x1E, 0x3A, 0x8A, 0xB4);
    public static final Color ZONE = new Color(0xC62828);
    public static final Color TEXT = new Color(0x1A1A1A);
    public static final Color IR_HIT = new Color(0xD0, 0x30, 0x30, 0xC0);
    public static final Color IR_FREE = new Color(0x60, 0x60, 0x60, 0x50);
    public static final Color CAMERA = new Color(0x30, 0x80, 0xE0, 0x30);
    public static final Color RADIO = new Color(0x7B1FA2);

    /** The robots' colours, by the order they were added; far from the hazard's yellow and the mark's red. */
    private static final Color[] ROBOTS = {
        new Color(0x1565C0), new Color(0x00897B), new Color(0x8E24AA), new Color(0xEF6C00),
        new Color(0x5D4037), new Color(0x00ACC1), new Color(0x3949AB), new Color(0xC2185B)};

    private Palette() {
    }

    /** The colour of the robot added {@code index}-th (0 first); the colours repeat after eight. */
    public static Color robot(int index) {
        return ROBOTS[Math.floorMod(index, ROBOTS.length)];
    }

    /** {@code colour} with {@code alpha} 0 to 1. */
    static Color alpha(Color colour, double alpha) {
        int a = (int) Math.round(Math.max(0, Math.min(1, alpha)) * 255);
        return new Color(colour.getRed(), colour.getGreen(), colour.getBlue(), a);
    }
}
