package net.smc.sim.render;

import java.awt.Color;
import java.util.ArrayList;
import java.util.List;

/**
 * The 256 colours of the GIF frames: every colour of the {@link Palette} exactly, then a 6x6x6
 * cube and greys for the blends of antialiasing. Frames are mapped to the nearest colour without
 * dithering, so the flat floor stays flat and the film compresses well.
 */
final class GifPalette {
    private static final int CACHE_BITS = 15;
    private final int[] rgb;
    // the colours matched so far, by open addressing: colour, its index, whether the slot is used
    private final int[] cachedColour = new int[1 << CACHE_BITS];
    private final byte[] cachedIndex = new byte[1 << CACHE_BITS];
    private final boolean[] cachedSet = new boolean[1 << CACHE_BITS];
    private int cached;

    GifPalette() {
        List<Integer> colours = new ArrayList<>();
        for (Color c : new Color[] {Palette.BACKGROUND, Palette.FLOOR, Palette.GRID, Palette.WALL, Palette.DOOR_CLOSED,
            Palette.DOOR_OPEN, Palette.OBSTACLE, Palette.HAZARD, Palette.HAZARD_EDGE, Palette.SOLDIER, Palette.STATION,
            Palette.MARK, Palette.ZONE, Palette.TEXT, Palette.RADIO, blendOnFloor(Palette.HAZARD_REACH),
            blendOnFloor(Palette.CAMERA)}) {
            add(colours, c.getRGB());
        }
        for (int i = 0; i < 8; i++) {
            add(colours, Palette.robot(i).getRGB());
            add(colours, Palette.robot(i).darker().getRGB());
        }
        for (int r = 0; r < 6; r++) {
            for (int g = 0; g < 6; g++) {
                for (int b = 0; b < 6; b++) {
                    add(colours, 0xFF000000 | (r * 51) << 16 | (g * 51) << 8 | b * 51);
                }
            }
        }
        for (int grey = 0x08; grey < 0x100 && colours.size() < 256; grey += 0x20) {
            add(colours, 0xFF000000 | grey * 0x010101);
        }
        while (colours.size() < 256) {
            colours.add(0xFF000000);
        }
        rgb = colours.stream().limit(256).mapToInt(Integer::intValue).toArray();
    }

    /** The 256 colours, 0xRRGGBB (alpha bits set). */
    int[] colours() {
        return rgb.clone();
    }

    /**
     * The index of the nearest colour for every pixel of {@code pixels} (0xRRGGBB, alpha ignored),
     * into {@code out}. Not thread-safe: it keeps the colours it has matched.
     */
    void indices(int[] pixels, byte[] out) {
        int last = ~pixels[0];   // not equal to the first pixel
        byte lastIndex = 0;
        for (int i = 0; i < pixels.length; i++) {
            int argb = pixels[i] | 0xFF000000;
            if (argb != last) {
                last = argb;
                lastIndex = index(argb);
            }
            out[i] = lastIndex;
        }
    }

    private byte index(int argb) {
        int slot = (argb * 0x9E3779B1) >>> (32 - CACHE_BITS);
        while (true) {
            if (cachedColour[slot] == argb && cachedSet[slot]) {
                return cachedIndex[slot];
            }
            if (!cachedSet[slot]) {
                break;
            }
            slot = (slot + 1) & (cachedColour.length - 1);
        }
        if (cached >= cachedColour.length / 2) {
            // more distinct colours than antialiasing makes in practice: start the cache afresh
            java.util.Arrays.fill(cachedSet, false);
            cached = 0;
            return index(argb);
        }
        byte best = nearest(argb);
        cachedColour[slot] = argb;
        cachedIndex[slot] = best;
        cachedSet[slot] = true;
        cached++;
        return best;
    }

    private byte nearest(int argb) {
        int best = 0;
        long bestDistance = Long.MAX_VALUE;
        for (int i = 0; i < rgb.length; i++) {
            int dr = (argb >> 16 & 0xFF) - (rgb[i] >> 16 & 0xFF);
            int dg = (argb >> 8 & 0xFF) - (rgb[i] >> 8 & 0xFF);
            int db = (argb & 0xFF) - (rgb[i] & 0xFF);
            long d = 3L * dr * dr + 4L * dg * dg + 2L * db * db;
            if (d < bestDistance) {
                bestDistance = d;
                best = i;
            }
        }
        return (byte) best;
    }

    private static void add(List<Integer> colours, int argb) {
        if (!colours.contains(argb | 0xFF000000)) {
            colours.add(argb | 0xFF000000);
        }
    }

    private static Color blendOnFloor(Color translucent) {
        double a = translucent.getAlpha() / 255.0;
        return new Color((int) Math.round(translucent.getRed() * a + Palette.FLOOR.getRed() * (1 - a)),
                (int) Math.round(translucent.getGreen() * a + Palette.FLOOR.getGreen() * (1 - a)),
                (int) Math.round(translucent.getBlue() * a + Palette.FLOOR.getBlue() * (1 - a)));
    }
}
