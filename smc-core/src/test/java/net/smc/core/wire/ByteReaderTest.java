package net.smc.core.wire;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class ByteReaderTest {
    /** A format whose errors say everything the reader passed on. */
    private static final WireErrors<Exception> PLAIN = (problem, at, field, rule) ->
            new Exception(problem + " " + field + " at " + at + ": " + rule);

    private static ByteReader<Exception> reader(int start, int... bytes) {
        byte[] b = new byte[bytes.length];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) bytes[i];
        }
        return new ByteReader<>(PLAIN, b, start, b.length);
    }

    @Test
    void readsBigEndianFields() throws Exception {
        ByteReader<Exception> in = reader(0, 0xFF, 0x12, 0x34, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 2);
        assertEquals(0xFF, in.u8("a"));
        assertEquals(0x1234, in.u16("b"));
        assertEquals(256, in.i32("c"));
        assertEquals(2L, in.i64("d"));
        assertEquals(0, in.remaining());
    }

    @Test
    void truncatedField_isReportedThroughTheFormatAtItsOffsetFromTheStart() {
        ByteReader<Exception> in = reader(2, 9, 9, 1, 2, 3);
        Exception e = assertThrows(Exception.class, () -> {
            in.u8("kind");
            in.i32("stamp");
        });
        assertEquals("TRUNCATED stamp at 1: truncated: needs 4 bytes, 2 left", e.getMessage());
        assertEquals(3, in.position());
    }

    @Test
    void truncatedLength_goesToItsOwnHook() {
        WireErrors<Exception> errors = new WireErrors<>() {
            @Override
            public Exception error(WireProblem problem, int offset, String field, String rule) {
                return new Exception(field + ": " + rule);
            }

            @Override
            public Exception truncatedLength(int offset, String field, int needed, int left) {
                return new Exception("the length of " + field + " needs " + needed + ", " + left + " left");
            }
        };
        ByteReader<Exception> in = new ByteReader<>(errors, new byte[] {1}, 0, 1);
        Exception e = assertThrows(Exception.class, () -> in.length16("name"));
        assertEquals("the length of name needs 2, 1 left", e.getMessage());
    }

    @Test
    void take_checksBeforeMovingAndReturnsTheIndex() throws Exception {
        ByteReader<Exception> in = reader(1, 0, 7, 8, 9);
        assertEquals(1, in.take(2, "x"));
        assertArrayEquals(new byte[] {9}, in.bytes(1, "y"));
        assertThrows(Exception.class, () -> in.take(1, "z"));
    }

    @Test
    void varint_roundTripsAtEveryLengthAndIsShortest() throws Exception {
        long[] values = {0, 1, 127, 128, 16_383, 16_384, 1L << 35, Long.MAX_VALUE};
        int[] lengths = {1, 1, 1, 2, 2, 3, 6, 9};
        for (int i = 0; i < values.length; i++) {
            ByteWriter w = ByteWriter.growing(16, 64, IllegalStateException::new);
            w.varint(values[i]);
            byte[] b = w.toByteArray();
            assertEquals(lengths[i], b.length, "bytes of " + values[i]);
            ByteReader<Exception> in = new ByteReader<>(PLAIN, b, 0, b.length);
            assertEquals(values[i], in.varint("v"));
            assertEquals(0, in.remaining());
        }
        assertThrows(IllegalArgumentException.class, () -> ByteWriter.growing(16, 64, IllegalStateException::new).varint(-1));
    }

    @Test
    void varint_refusesALongerFormThanNeededAndOverflow() {
        Exception padded = assertThrows(Exception.class, () -> reader(0, 0x81, 0x00).varint("version"));
        assertEquals("MALFORMED version at 0: is a varint not in its shortest form", padded.getMessage());
        Exception tooBig = assertThrows(Exception.class,
                () -> reader(0, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x80, 0x01).varint("version"));
        assertEquals("MALFORMED version at 0: is a varint above " + Long.MAX_VALUE, tooBig.getMessage());
        Exception cut = assertThrows(Exception.class, () -> reader(1, 0, 0x80).varint("version"));
        assertEquals("TRUNCATED version at 1: truncated: needs 1 bytes, 0 left", cut.getMessage());
    }
}
