package net.smc.core.wire;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class ByteWriterTest {
    @Test
    void writesBigEndianFieldsAndLengthPrefixedUtf8() {
        ByteWriter w = ByteWriter.growing(1, 100, IllegalStateException::new);
        w.u8(1);
        w.u16(0x0203);
        w.i32(4);
        w.string8("é");
        w.string16("a");
        assertArrayEquals(new byte[] {1, 2, 3, 0, 0, 0, 4, 2, (byte) 0xC3, (byte) 0xA9, 0, 1, 'a'}, w.toByteArray());
    }

    @Test
    void growingWriter_throwsTheFormatsOverflowPastItsLimit() {
        ByteWriter w = ByteWriter.growing(2, 9, () -> new IllegalArgumentException("form over 9 bytes"));
        w.i64(1);
        w.u8(2);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> w.u8(3));
        assertEquals("form over 9 bytes", e.getMessage());
        assertEquals(9, w.position());
    }

    @Test
    void fixedWriter_writesBetweenStartAndLimitOfTheCallersArray() {
        byte[] buf = new byte[6];
        ByteWriter w = new ByteWriter(buf, IllegalStateException::new);
        w.reset(2, 4);
        w.u16(0xABCD);
        assertThrows(IllegalStateException.class, () -> w.u8(0));
        assertArrayEquals(new byte[] {0, 0, (byte) 0xAB, (byte) 0xCD, 0, 0}, buf);
        assertArrayEquals(new byte[] {(byte) 0xAB, (byte) 0xCD}, w.toByteArray());
    }
}
