package net.smc.sim.render;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.awt.image.IndexColorModel;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The 256 colours of the GIF frames: every colour of the {@link Palette} exactly, then a 6x6x6
 * cube and greys for the blends of antialiasing. Frames are mapped to the nearest colour without
 * dithering, so the flat floor stays flat and the film compresses well.
 */
final class GifPalette {
    private final IndexColorModel model;
    private final int[] rgb;
    private final Map<Integer, Byte> nearest = new HashMap<>();

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
        model = new IndexColorModel(8, rgb.length, rgb, 0, false, -1, java.awt.image.DataBuffer.TYPE_BYTE);
    }

    /** The colours as a GIF {@code LocalColorTable} metadata node (the writer's default table is not this one). */
    javax.imageio.metadata.IIOMetadataNode colourTable() {
        javax.imageio.metadata.IIOMetadataNode table = new javax.imageio.metadata.IIOMetadataNode("LocalColorTable");
        table.setAttribute("sizeOfLocalColorTable", Integer.toString(rgb.length));
        table.setAttribute("sortFlag", "FALSE");
        for (int i = 0; i < rgb.length; i++) {
            javax.imageio.metadata.IIOMetadataNode entry = new javax.imageio.metadata.IIOMetadataNode("ColorTableEntry");
            entry.setAttribute("index", Integer.toString(i));
            entry.setAttribute("red", Integer.toString(rgb[i] >> 16 & 0xFF));
            entry.setAttribute("green", Integer.toString(rgb[i] >> 8 & 0xFF));
            entry.setAttribute("blue", Integer.toString(rgb[i] & 0xFF));
            table.appendChild(entry);
        }
        return table;
    }

    /** {@code image} in these colours. */
    BufferedImage map(BufferedImage image) {
        BufferedImage out = new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_BYTE_INDEXED, model);
        byte[] data = ((java.awt.image.DataBufferByte) out.getRaster().getDataBuffer()).getData();
        int width = image.getWidth();
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < width; x++) {
                data[y * width + x] = index(image.getRGB(x, y) | 0xFF000000);
            }
        }
        return out;
    }

    private byte index(int argb) {
        Byte known = nearest.get(argb);
        if (known == null) {
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
            known = (byte) best;
            nearest.put(argb, known);
        }
        return known;
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
