package net.smc.sim.render;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;

/**
 * Writes an animated GIF89a of same-sized frames in one fixed 256-colour table: the global colour
 * table, a NETSCAPE2.0 extension that loops the film for ever, and per frame a graphic control
 * extension (its delay) and the frame's pixels compressed with GIF's variable-length LZW (8-bit
 * codes, clear code 256, end code 257, codes of 9 to 12 bits, the table cleared when full).
 * Frames are compressed one by one ({@link #compress}), on any thread, and put together by
 * {@link #write}; the bytes depend on the pixels alone.
 */
final class GifEncoder {
    private static final int CLEAR = 256;
    private static final int END = 257;
    private static final int FIRST_FREE = 258;
    private static final int MAX_CODES = 4096;
    private static final int TABLE = 1 << 14;   // open addressing over (prefix, byte) keys; > MAX_CODES

    // the string table of the frame being compressed: key (prefix << 8 | byte) + 1 -> code, 0 empty
    private final int[] keys = new int[TABLE];
    private final int[] codes = new int[TABLE];
    private final ByteArrayOutputStream out = new ByteArrayOutputStream(1 << 16);
    private final byte[] block = new byte[255];
    private int blockSize;
    private long bits;
    private int bitCount;
    private int codeSize;
    private int nextCode;

    /**
     * The LZW image data of one frame: the minimum code size (8), the compressed codes in
     * sub-blocks of at most 255 bytes, and the block terminator.
     *
     * @param pixels colour indices, row by row
     */
    byte[] compress(byte[] pixels) {
        out.reset();
        blockSize = 0;
        bits = 0;
        bitCount = 0;
        out.write(8);
        codeSize = 9;
        clearTable();
        emit(CLEAR);
        if (pixels.length > 0) {
            int prefix = pixels[0] & 0xFF;
            for (int i = 1; i < pixels.length; i++) {
                int next = pixels[i] & 0xFF;
                int key = (prefix << 8 | next) + 1;
                int slot = slot(key);
                if (keys[slot] == key) {
                    prefix = codes[slot];
                    continue;
                }
                emit(prefix);
                if (nextCode < MAX_CODES) {
                    keys[slot] = key;
                    codes[slot] = nextCode++;
                } else {
                    emit(CLEAR);   // the table is full: start afresh
                }
                prefix = next;
            }
            emit(prefix);
        }
        emit(END);
        if (bitCount > 0) {
            put((int) bits & 0xFF);
        }
        if (blockSize > 0) {
            flushBlock();
        }
        out.write(0);
        return out.toByteArray();
    }

    /** Where {@code key} is, or the empty slot where it would go. */
    private int slot(int key) {
        int h = (key * 0x9E3779B1) >>> 18;   // 14 bits
        while (keys[h] != 0 && keys[h] != key) {
            h = (h + 1) & (TABLE - 1);
        }
        return h;
    }

    private void clearTable() {
        Arrays.fill(keys, 0);
        nextCode = FIRST_FREE;
    }

    /**
     * Writes {@code code} in the current code size, then widens the codes once the table holds an
     * entry the current size cannot name (the decoder, one entry behind, widens at the same code).
     */
    private void emit(int code) {
        bits |= (long) code << bitCount;
        bitCount += codeSize;
        while (bitCount >= 8) {
            put((int) bits & 0xFF);
            bits >>>= 8;
            bitCount -= 8;
        }
        if (code == CLEAR) {
            clearTable();
            codeSize = 9;
        } else if (nextCode > (1 << codeSize) - 1 && codeSize < 12) {
            codeSize++;
        }
    }

    private void put(int b) {
        block[blockSize++] = (byte) b;
        if (blockSize == block.length) {
            flushBlock();
        }
    }

    private void flushBlock() {
        out.write(blockSize);
        out.write(block, 0, blockSize);
        blockSize = 0;
    }

    /**
     * Writes the whole film.
     *
     * @param colours     the 256 colours, 0xRRGGBB
     * @param frames      each frame's {@link #compress}ed data
     * @param delays      each frame's delay, hundredths of a second (1 to 65,535)
     */
    static void write(OutputStream to, int width, int height, int[] colours, List<byte[]> frames, int[] delays)
            throws IOException {
        if (colours.length != 256) {
            throw new IllegalArgumentException("a GIF colour table of " + colours.length + " colours; it must have 256");
        }
        to.write("GIF89a".getBytes(StandardCharsets.US_ASCII));
        short16(to, width);
        short16(to, height);
        to.write(0xF7);   // a global colour table of 2^(7+1) entries, 8 bits per primary
        to.write(0);      // background colour index
        to.write(0);      // no aspect ratio given
        for (int c : colours) {
            to.write(c >> 16 & 0xFF);
            to.write(c >> 8 & 0xFF);
            to.write(c & 0xFF);
        }
        to.write(new byte[] {0x21, (byte) 0xFF, 11});
        to.write("NETSCAPE2.0".getBytes(StandardCharsets.US_ASCII));
        to.write(new byte[] {3, 1, 0, 0, 0});   // sub-block 1, loop count 0: for ever
        for (int i = 0; i < frames.size(); i++) {
            to.write(new byte[] {0x21, (byte) 0xF9, 4, 0});   // graphic control: no disposal, no transparency
            short16(to, Math.max(1, Math.min(65_535, delays[i])));
            to.write(new byte[] {0, 0});
            to.write(0x2C);   // image descriptor: the whole screen, no local table, not interlaced
            short16(to, 0);
            short16(to, 0);
            short16(to, width);
            short16(to, height);
            to.write(0);
            to.write(frames.get(i));
        }
        to.write(0x3B);
    }

    private static void short16(OutputStream to, int value) throws IOException {
        to.write(value & 0xFF);
        to.write(value >> 8 & 0xFF);
    }
}
