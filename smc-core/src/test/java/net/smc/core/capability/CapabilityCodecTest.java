package net.smc.core.capability;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;

/** The wire form's layout and each of its rules, one rule a test. */
class CapabilityCodecTest {
    private static final CapabilityCodec CODEC = CapabilityCodec.STANDARD;
    private static final CapabilityDescription FULL = CapabilityDescription.of("uav1", Set.of("motion", "video"),
            List.of(new TaskDescription("Explorer",
                    List.of(new OperationDescription("moveTo", List.of("double", "double"))),
                    List.of(new EventDescription("obstacle", List.of(new EventDescription.Attribute("x", "double")))))));

    /** Builds wire bytes by hand, independently of the writer. */
    private static final class Bytes {
        final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        final DataOutputStream out = new DataOutputStream(bytes);

        Bytes u8(int v) throws IOException {
            out.writeByte(v);
            return this;
        }

        Bytes u16(int v) throws IOException {
            out.writeShort(v);
            return this;
        }

        Bytes str(String s) throws IOException {
            byte[] b = s.getBytes(StandardCharsets.UTF_8);
            out.writeShort(b.length);
            out.write(b);
            return this;
        }

        Bytes raw(byte... b) throws IOException {
            out.write(b);
            return this;
        }

        byte[] get() {
            return bytes.toByteArray();
        }
    }

    private static Bytes summaryHeader() throws IOException {
        return new Bytes().u8('S').u8(1).str("uav1");
    }

    @Test
    void summary_hasTheDocumentedLayout() throws Exception {
        CapabilitySummary s = new CapabilitySummary("uav1", new TreeSet<>(Set.of("video", "motion")), new TreeSet<>(Set.of("Explorer")));
        byte[] expected = summaryHeader().u16(2).str("motion").str("video").u16(1).str("Explorer").get();
        assertArrayEquals(expected, CODEC.encode(s));
        assertEquals(s, CODEC.decodeSummary(expected));
    }

    @Test
    void description_hasTheDocumentedLayout() throws Exception {
        byte[] expected = new Bytes().u8('D').u8(1).str("uav1").u16(2).str("motion").str("video")
                .u16(1).str("Explorer")
                .u16(1).str("moveTo").u16(2).str("double").str("double")
                .u16(1).str("obstacle").u16(1).str("x").str("double").get();
        assertArrayEquals(expected, CODEC.encode(FULL));
        assertEquals(FULL, CODEC.decodeDescription(expected));
    }

    @Test
    void read_isSelfDelimitingAndLeavesTheRestOfTheBuffer() throws Exception {
        byte[] one = CODEC.encode(FULL.summary());
        byte[] two = CODEC.encode(FULL);
        ByteBuffer buffer = ByteBuffer.allocate(one.length + two.length + 3).put(one).put(two).put(new byte[] {7, 8, 9}).flip();
        assertEquals(FULL.summary(), CODEC.readSummary(buffer));
        assertEquals(FULL, CODEC.readDescription(buffer));
        assertEquals(3, buffer.remaining());
    }

    @Test
    void read_leavesThePositionOnAnError() {
        ByteBuffer buffer = ByteBuffer.wrap(new byte[] {'S', 1, 0});
        assertThrows(CapabilityFormatException.class, () -> CODEC.readSummary(buffer));
        assertEquals(0, buffer.position());
    }

    @Test
    void decode_refusesTrailingBytes() throws Exception {
        byte[] bytes = new Bytes().raw(CODEC.encode(FULL.summary())).u8(0).get();
        CapabilityFormatException e = assertThrows(CapabilityFormatException.class, () -> CODEC.decodeSummary(bytes));
        assertEquals("capability summary: 1 bytes after the end of the form at byte " + (bytes.length - 1) + " of " + bytes.length,
                e.getMessage());
    }

    @Test
    void decode_refusesTheOtherKind() {
        byte[] description = CODEC.encode(FULL);
        CapabilityFormatException e = assertThrows(CapabilityFormatException.class, () -> CODEC.decodeSummary(description));
        assertEquals("capability summary: kind at byte 0: expected 'S', found a capability description", e.getMessage());
    }

    @Test
    void decode_refusesAnUnknownKindByte() {
        CapabilityFormatException e = assertThrows(CapabilityFormatException.class,
                () -> CODEC.decodeDescription(new byte[] {0x7f, 1}));
        assertEquals("capability description: kind at byte 0: expected 'D', found 0x7f", e.getMessage());
    }

    @Test
    void decode_refusesAnotherVersion() {
        CapabilityFormatException e = assertThrows(CapabilityFormatException.class, () -> CODEC.decodeSummary(new byte[] {'S', 2}));
        assertEquals("capability summary: version at byte 1: version 2 is not supported; this reader knows version 1",
                e.getMessage());
    }

    @Test
    void decode_refusesTruncatedInputNamingTheField() throws Exception {
        byte[] bytes = summaryHeader().u16(1).u16(5).raw((byte) 'v').get();
        CapabilityFormatException e = assertThrows(CapabilityFormatException.class, () -> CODEC.decodeSummary(bytes));
        assertEquals("capability summary: resources[0] at byte 12: truncated: needs 5 bytes, 1 left", e.getMessage());
        assertEquals(12, e.offset());
    }

    @Test
    void decode_refusesAStringOverTheLimit_beforeReadingIt() throws Exception {
        byte[] bytes = summaryHeader().u16(1).u16(256).get();
        CapabilityFormatException e = assertThrows(CapabilityFormatException.class, () -> CODEC.decodeSummary(bytes));
        assertEquals("capability summary: resources[0] at byte 10: a string of 256 bytes; the limit is 255", e.getMessage());
    }

    @Test
    void decode_refusesACountOverTheLimit_beforeReadingTheEntries() throws Exception {
        byte[] bytes = summaryHeader().u16(0xffff).get();
        CapabilityFormatException e = assertThrows(CapabilityFormatException.class, () -> CODEC.decodeSummary(bytes));
        assertEquals("capability summary: resources at byte 8: 65535 entries; the limit is 256", e.getMessage());
    }

    @Test
    void decode_namesNestedFieldsByTheirRecordPath() throws Exception {
        byte[] bytes = new Bytes().u8('D').u8(1).str("uav1").u16(0).u16(1).str("Explorer").u16(1).str("moveTo").u16(300).get();
        CapabilityFormatException e = assertThrows(CapabilityFormatException.class, () -> CODEC.decodeDescription(bytes));
        assertTrue(e.getMessage().startsWith("capability description: tasks[0].operations[0].argumentTypes at byte "),
                e.getMessage());
        assertTrue(e.getMessage().endsWith(": 300 entries; the limit is 256"), e.getMessage());
    }

    @Test
    void decode_refusesInvalidUtf8() throws Exception {
        byte[] bytes = new Bytes().u8('S').u8(1).u16(2).raw((byte) 0xc0, (byte) 0x80).u16(0).u16(0).get();
        CapabilityFormatException e = assertThrows(CapabilityFormatException.class, () -> CODEC.decodeSummary(bytes));
        assertEquals("capability summary: vehicle at byte 2: not valid UTF-8", e.getMessage());
    }

    @Test
    void decode_refusesASetOutOfOrderOrWithRepeats() throws Exception {
        byte[] unsorted = summaryHeader().u16(2).str("video").str("motion").u16(0).get();
        CapabilityFormatException e = assertThrows(CapabilityFormatException.class, () -> CODEC.decodeSummary(unsorted));
        assertEquals("capability summary: resources[1] at byte 17: 'motion' does not come after 'video';"
                + " a set is written in ascending order without repeats", e.getMessage());
        byte[] repeated = summaryHeader().u16(0).u16(2).str("A").str("A").get();
        assertThrows(CapabilityFormatException.class, () -> CODEC.decodeSummary(repeated));
    }

    @Test
    void decode_refusesAFormLongerThanTheLimit() throws Exception {
        CapabilityCodec small = new CapabilityCodec(new CapabilityCodec.Limits(255, 256, 16));
        byte[] bytes = summaryHeader().u16(1).str("a-rather-long-resource").u16(0).get();
        CapabilityFormatException e = assertThrows(CapabilityFormatException.class, () -> small.decodeSummary(bytes));
        assertEquals("capability summary: resources[0] at byte 12: the form is longer than the limit of 16 bytes", e.getMessage());
    }

    @Test
    void encode_refusesAStringOverTheLimitNamingTheField() {
        CapabilityDescription d = CapabilityDescription.of("uav1", Set.of(), List.of(TaskDescription.empty("x".repeat(256))));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CODEC.encode(d));
        assertEquals("capability description: tasks[0].task is 256 bytes of UTF-8; the limit is 255", e.getMessage());
    }

    @Test
    void encode_refusesACountOverTheLimitNamingTheField() {
        List<String> many = new ArrayList<>();
        for (int i = 0; i < 257; i++) {
            many.add("r" + i);
        }
        CapabilitySummary s = new CapabilitySummary("uav1", new TreeSet<>(many), new TreeSet<>());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CODEC.encode(s));
        assertEquals("capability summary: resources has 257 entries; the limit is 256", e.getMessage());
    }

    @Test
    void encode_refusesAFormLongerThanTheLimit() {
        CapabilityCodec small = new CapabilityCodec(new CapabilityCodec.Limits(255, 256, 16));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> small.encode(FULL));
        assertEquals("capability description is longer than 16 bytes encoded, the limit", e.getMessage());
    }

    @Test
    void encode_refusesAnUnpairedSurrogate() {
        CapabilitySummary s = new CapabilitySummary("uav\ud800", new TreeSet<>(), new TreeSet<>());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CODEC.encode(s));
        assertEquals("capability summary: vehicle is not well-formed Unicode (it has an unpaired surrogate)", e.getMessage());
    }

    @Test
    void encode_refusesANullField() {
        CapabilitySummary s = new CapabilitySummary(null, new TreeSet<>(), new TreeSet<>());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CODEC.encode(s));
        assertEquals("capability summary: vehicle is null", e.getMessage());
    }

    @Test
    void limits_refuseValuesTheFormatCannotCarry() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new CapabilityCodec.Limits(70_000, 1, 100));
        assertEquals("maxStringBytes is 70000; it must be 1 to 65535", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new CapabilityCodec.Limits(1, 0, 100));
        assertThrows(IllegalArgumentException.class, () -> new CapabilityCodec.Limits(1, 1, 15));
    }
}
