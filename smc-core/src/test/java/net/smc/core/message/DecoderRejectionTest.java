package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

import java.nio.ByteBuffer;
import org.junit.jupiter.api.Test;

/** Each rule of the decoder, broken once: the reason, the detail naming field, value and rule, and the counter. */
class DecoderRejectionTest {
    private final Codec codec = new Codec();

    private DecodeResult.Rejected reject(byte[] datagram, RejectReason reason, String detail) {
        long before = codec.decoder.rejected(reason);
        DecodeResult.Rejected r = Codec.rejected(codec.decode(datagram));
        assertEquals(reason, r.reason(), r.detail());
        assertEquals(detail, r.detail());
        assertEquals(before + 1, codec.decoder.rejected(reason));
        return r;
    }

    /** A valid heartbeat payload after the given role bytes. */
    private static Raw heartbeat() {
        return Raw.of(MessageType.HEARTBEAT).str8("relay").u8(1).u8(0).u8(0);  // varints: epoch 1, state 0, status 0
    }

    @Test
    void theValidBaseline_decodes() {
        assertEquals(new Heartbeat("relay", 1, 0), Codec.decoded(codec.decode(heartbeat().datagram())).body());
    }

    @Test
    void datagramOver1400Bytes_isOversized() {
        reject(new byte[1_401], RejectReason.OVERSIZED, "datagram of 1401 bytes: datagram is 1401 bytes; at most 1400"
                + " are allowed");
    }

    @Test
    void directBufferOver1400Bytes_isOversized() {
        DecodeResult r = codec.decoder.decode(ByteBuffer.allocateDirect(2_000));
        assertEquals(RejectReason.OVERSIZED, Codec.rejected(r).reason());
    }

    @Test
    void emptyDatagram_isTruncated() {
        reject(new byte[0], RejectReason.TRUNCATED, "datagram of 0 bytes: magic needs 2 bytes but 0 remain");
    }

    @Test
    void foreignMagic_isBadMagic() {
        Raw raw = heartbeat();
        raw.magic = 0x4745;
        reject(raw.datagram(), RejectReason.BAD_MAGIC, "datagram of 26 bytes: magic is 0x4745; a datagram starts with"
                + " 0x534D");
    }

    @Test
    void laterVersion_isUnknownVersion() {
        Raw raw = heartbeat();
        raw.version = 3;
        reject(raw.datagram(), RejectReason.UNKNOWN_VERSION, "datagram of 26 bytes: version is 3; this build reads"
                + " version 2");
    }

    @Test
    void unassignedTypeCode_isUnknownType() {
        for (int code : new int[] {0x00, 0x16, 0xFE}) {
            Raw raw = heartbeat();
            raw.type = code;
            reject(raw.datagram(), RejectReason.UNKNOWN_TYPE, String.format("datagram of 26 bytes: type code 0x%02X is"
                    + " not assigned to a message type", code));
        }
    }

    @Test
    void senderOver64Bytes_isOversized() {
        Raw raw = heartbeat();
        raw.sender = new byte[65];
        reject(raw.datagram(), RejectReason.OVERSIZED, "datagram of 87 bytes: sender is 65 bytes; at most 64 are"
                + " allowed");
    }

    @Test
    void senderLeftToTheTransport_withoutANamedSender_isMalformed() {
        Raw raw = heartbeat();
        raw.sender = new byte[0];
        reject(raw.datagram(), RejectReason.MALFORMED, "datagram of 22 bytes: the sender length is 0, which leaves the"
                + " sender to a transport that proves it, and this datagram came without one");
    }

    @Test
    void senderLeftToTheTransport_isTheSenderItNames() {
        Raw raw = heartbeat();
        raw.sender = new byte[0];
        byte[] d = raw.datagram();
        Envelope e = Codec.decoded(codec.decoder.decode("uav9", d, 0, d.length));
        assertEquals("uav9", e.sender());
        assertEquals(new Heartbeat("relay", 1, 0), e.body());
    }

    @Test
    void aHeaderThatNamesItsSender_keepsIt_whateverTheTransportNames() {
        byte[] d = heartbeat().datagram();
        assertEquals("uav1", Codec.decoded(codec.decoder.decode("uav9", d, 0, d.length)).sender(),
                "the Communication-Manager compares the two and drops a message whose names differ");
    }

    @Test
    void bytesAfterTheLastField_areMalformed() {
        reject(heartbeat().u8(0).datagram(), RejectReason.MALFORMED, "HEARTBEAT from 'uav1' (id 7): 1 bytes follow"
                + " the last field");
    }

    @Test
    void fieldCutShort_isTruncated() {
        reject(Raw.of(MessageType.HEARTBEAT).str8("relay").u8(1).u8(0x80).datagram(), RejectReason.TRUNCATED,
                "HEARTBEAT from 'uav1' (id 7): state needs 1 bytes but 0 remain");
    }

    @Test
    void stringLengthPastTheEnd_isTruncatedBeforeAnyAllocation() {
        reject(Raw.of(MessageType.POLICY_REPLY).i64(1).str8("u").i32(1).u16(60_000).u8(WireFormat.POLICY_TEXT_PLAIN).raw(new byte[10]).datagram(),
                RejectReason.TRUNCATED, "POLICY_REPLY from 'uav1' (id 7): text needs 60000 bytes but 10 remain");
    }

    @Test
    void overlongUtf8_isMalformed() {
        reject(Raw.of(MessageType.HEARTBEAT).u8(2).raw((byte) 0xC0, (byte) 0x80).u8(1).u8(0).u8(0).datagram(),
                RejectReason.MALFORMED, "HEARTBEAT from 'uav1' (id 7): role is not well-formed UTF-8");
    }

    @Test
    void encodedSurrogate_isMalformed() {
        reject(Raw.of(MessageType.LEAVE).u8(3).raw((byte) 0xED, (byte) 0xA0, (byte) 0x80).datagram(),
                RejectReason.MALFORMED, "LEAVE from 'uav1' (id 7): reason is not well-formed UTF-8");
    }

    @Test
    void echoOfEightBytes_isMalformed() {
        reject(Raw.of(MessageType.ECHO).i64(5).datagram(), RejectReason.MALFORMED,
                "ECHO from 'uav1' (id 7): 4 bytes follow the last field");
    }

    @Test
    void varintInALongerFormThanNeeded_isMalformed() {
        reject(Raw.of(MessageType.HEARTBEAT).str8("relay").u8(0x81).u8(0).u8(0).u8(0).datagram(), RejectReason.MALFORMED,
                "HEARTBEAT from 'uav1' (id 7): epoch is a varint not in its shortest form");
    }

    @Test
    void stateBeyondAnInt_isMalformed() {
        reject(Raw.of(MessageType.HEARTBEAT).str8("relay").u8(1).raw((byte) 0x80, (byte) 0x80, (byte) 0x80, (byte) 0x80,
                (byte) 0x08).u8(0).datagram(), RejectReason.MALFORMED,
                "HEARTBEAT from 'uav1' (id 7): state is 2147483648; at most 2147483647");
    }

    @Test
    void booleanOtherThan0Or1_isMalformed() {
        reject(Raw.of(MessageType.ASSIGNMENT_RESPONSE).i64(1).str8("r").u8(2).str8("").datagram(),
                RejectReason.MALFORMED, "ASSIGNMENT_RESPONSE from 'uav1' (id 7): accepted is 2; a boolean is 0 or 1");
    }

    @Test
    void unassignedValueTag_isMalformed() {
        reject(Raw.of(MessageType.ROLE_EVENT).str8("r").str8("e").u8(1).u8(9).datagram(), RejectReason.MALFORMED,
                "ROLE_EVENT from 'uav1' (id 7): values has value tag 9; tags are 0 to 5");
    }

    @Test
    void numberWithARedundantSignByte_isMalformed() {
        reject(Raw.of(MessageType.ROLE_EVENT).str8("r").str8("e").u8(1).u8(4).i32(0).u8(2).raw((byte) 0, (byte) 5)
                .datagram(), RejectReason.MALFORMED, "ROLE_EVENT from 'uav1' (id 7): values is a number with a"
                + " redundant sign byte; numbers are minimal two's complement");
    }

    @Test
    void numberOf65Bytes_isOversized() {
        reject(Raw.of(MessageType.ROLE_EVENT).str8("r").str8("e").u8(1).u8(4).i32(0).u8(65).raw(new byte[65])
                .datagram(), RejectReason.OVERSIZED, "ROLE_EVENT from 'uav1' (id 7): values is a number of 65 bytes;"
                + " at most 64 are allowed");
    }

    @Test
    void listsNestedFiveDeep_areMalformed() {
        Raw raw = Raw.of(MessageType.INVOCATION).str8("r").str8("o").u8(1);
        for (int i = 0; i < 5; i++) {
            raw.u8(5).u8(1);
        }
        reject(raw.u8(0).datagram(), RejectReason.MALFORMED, "INVOCATION from 'uav1' (id 7): args nests lists 5 deep;"
                + " at most 4 are allowed");
    }

    @Test
    void acksOver128Ids_areOversized() {
        Raw raw = Raw.of(MessageType.ACKS).u8(129);
        for (int i = 0; i < 129; i++) {
            raw.i64(i);
        }
        reject(raw.datagram(), RejectReason.OVERSIZED, "ACKS from 'uav1' (id 7): acked has 129 elements; at most"
                + " 128 are allowed");
    }

    @Test
    void acksCountBeyondTheRemainingBytes_isTruncated() {
        reject(Raw.of(MessageType.ACKS).u8(3).i64(1).i64(2).datagram(), RejectReason.TRUNCATED,
                "ACKS from 'uav1' (id 7): acked has 3 elements but only 16 bytes remain");
    }

    @Test
    void acksWithNoIds_isAnInvalidField() {
        reject(Raw.of(MessageType.ACKS).u8(0).datagram(), RejectReason.INVALID_FIELD,
                "ACKS from 'uav1' (id 7): Acks.acked is empty; it must name 1 to 128 ids");
    }

    @Test
    void acksWithBytesAfterTheLastId_isMalformed() {
        reject(Raw.of(MessageType.ACKS).u8(1).i64(1).u8(0).datagram(), RejectReason.MALFORMED,
                "ACKS from 'uav1' (id 7): 1 bytes follow the last field");
    }

    @Test
    void listCountOverItsLimit_isOversized() {
        reject(Raw.of(MessageType.INVOCATION).str8("r").str8("o").u8(65).raw(new byte[65]).datagram(),
                RejectReason.OVERSIZED, "INVOCATION from 'uav1' (id 7): args has 65 elements; at most 64 are allowed");
    }

    @Test
    void listCountBeyondTheRemainingBytes_isTruncated() {
        reject(Raw.of(MessageType.INVOCATION).str8("r").str8("o").u8(60).raw(new byte[3]).datagram(),
                RejectReason.TRUNCATED, "INVOCATION from 'uav1' (id 7): args has 60 elements but only 3 bytes remain");
    }

    @Test
    void unsortedResourceSet_isMalformed() {
        reject(discoveryReplyWithResources("abc", "xyz", "xyz", "abc"), RejectReason.MALFORMED, UNSORTED);
    }

    @Test
    void repeatedResource_isMalformed() {
        reject(discoveryReplyWithResources("abc", "abd", "abc", "abc"), RejectReason.MALFORMED, REPEATED);
    }

    private static final String UNSORTED = "DISCOVERY_REPLY from 'uav1' (id 7): summary: capability summary:"
            + " resources[1] at byte 15: 'abc' does not come after 'xyz'; a set is written in ascending order without repeats";
    private static final String REPEATED = "DISCOVERY_REPLY from 'uav1' (id 7): summary: capability summary:"
            + " resources[1] at byte 15: 'abc' does not come after 'abc'; a set is written in ascending order without repeats";

    /**
     * A DISCOVERY_REPLY whose summary names resources {@code first} and {@code second} (a valid,
     * sorted pair of equal length), then has them rewritten in place to {@code a} and {@code b}.
     */
    private static byte[] discoveryReplyWithResources(String first, String second, String a, String b) {
        byte[] form = net.smc.core.capability.CapabilityCodec.STANDARD.encode(new net.smc.core.capability.CapabilitySummary(
                "uav2", new java.util.TreeSet<>(java.util.List.of(first, second)), new java.util.TreeSet<>()));
        overwrite(form, first, a);
        overwrite(form, second, b);
        return Raw.of(MessageType.DISCOVERY_REPLY).i64(1).str8("m").str8("").raw(form).datagram();   // free: holds nothing
    }

    /** Overwrites the last occurrence of {@code was} in {@code bytes} with {@code now} (same length, ASCII). */
    private static void overwrite(byte[] bytes, String was, String now) {
        byte[] from = was.getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        for (int at = bytes.length - from.length; at >= 0; at--) {
            if (java.util.Arrays.equals(bytes, at, at + from.length, from, 0, from.length)) {
                System.arraycopy(now.getBytes(java.nio.charset.StandardCharsets.US_ASCII), 0, bytes, at, from.length);
                return;
            }
        }
        throw new AssertionError("'" + was + "' is not in the encoded form");
    }

    @Test
    void failedResultWithAnEmptyError_isAnInvalidField() {
        reject(Raw.of(MessageType.INVOCATION_RESULT).i64(1).u8(0).str8("").datagram(), RejectReason.INVALID_FIELD,
                "INVOCATION_RESULT from 'uav1' (id 7): InvocationResult.error '' is 0 UTF-8 bytes; the error of a"
                        + " failed result must be 1 to 255 bytes");
    }

    /** A fragment frame of {@code POLICY_REPLY}. */
    private static Raw fragment(int type, int index, int count, int total, int chunk) {
        return new Raw(WireFormat.FRAGMENT_CODE).u8(type).u16(index).u16(count).i32(total).raw(new byte[chunk]);
    }

    @Test
    void fragmentOfAnUnknownType_isUnknownType() {
        reject(fragment(0x33, 0, 2, 100, 50).datagram(), RejectReason.UNKNOWN_TYPE, "FRAGMENT from 'uav1' (id 7):"
                + " fragment type code 0x33 is not a message type");
    }

    @Test
    void fragmentOfAFragment_isABadFragment() {
        reject(fragment(0xFF, 0, 2, 100, 50).datagram(), RejectReason.BAD_FRAGMENT, "FRAGMENT from 'uav1' (id 7):"
                + " fragment type code 0xFF is not a message type");
    }

    @Test
    void fragmentCountOfOne_isABadFragment() {
        reject(fragment(8, 0, 1, 50, 50).datagram(), RejectReason.BAD_FRAGMENT, "FRAGMENT from 'uav1' (id 7):"
                + " fragment count is 1; a fragmented message has 2 or more");
    }

    @Test
    void fragmentCountOver64_isOversized() {
        reject(fragment(8, 0, 65, 6_500, 100).datagram(), RejectReason.OVERSIZED, "FRAGMENT from 'uav1' (id 7):"
                + " fragment count is 65; at most 64 are allowed");
    }

    @Test
    void fragmentTotalOverTheLargestPayload_isOversized() {
        reject(fragment(8, 0, 2, 70_000, 100).datagram(), RejectReason.OVERSIZED, "FRAGMENT from 'uav1' (id 7):"
                + " fragment total is 70000 bytes; a message is at most 65535");
    }

    @Test
    void fragmentIndexAtTheCount_isABadFragment() {
        reject(fragment(8, 2, 2, 100, 50).datagram(), RejectReason.BAD_FRAGMENT, "FRAGMENT from 'uav1' (id 7):"
                + " fragment index is 2; it must be below the count 2");
    }

    @Test
    void fragmentWithTheWrongChunkLength_isABadFragment() {
        reject(fragment(8, 0, 2, 100, 49).datagram(), RejectReason.BAD_FRAGMENT, "FRAGMENT from 'uav1' (id 7):"
                + " fragment 0 of 2 of a 100-byte POLICY_REPLY must carry 50 bytes; it carries 49");
    }

    @Test
    void fragmentCountThatLeavesTheLastChunkEmpty_isABadFragment() {
        reject(fragment(8, 0, 4, 9, 3).datagram(), RejectReason.BAD_FRAGMENT, "FRAGMENT from 'uav1' (id 7):"
                + " 4 fragments cannot split 9 bytes (the last chunk would be empty)");
    }

    @Test
    void fragmentDisagreeingWithItsSiblings_isABadFragment() {
        assertInstanceOf(DecodeResult.FragmentPending.class, codec.decode(fragment(8, 0, 2, 100, 50).datagram()));
        reject(fragment(8, 1, 2, 98, 49).datagram(), RejectReason.BAD_FRAGMENT, "FRAGMENT from 'uav1' (id 7):"
                + " fragment 1 says 2 fragments of a 98-byte POLICY_REPLY; earlier fragments said 2 of a 100-byte"
                + " POLICY_REPLY");
    }

    @Test
    void reassembledPayloadThatBreaksARule_isRejectedAsReassembled() {
        assertInstanceOf(DecodeResult.FragmentPending.class, codec.decode(fragment(9, 0, 2, 20, 10).datagram()));
        reject(fragment(9, 1, 2, 20, 10).datagram(), RejectReason.INVALID_FIELD, "reassembled HEARTBEAT from 'uav1'"
                + " (id 7): Heartbeat.role '' is 0 UTF-8 bytes; a name must be 1 to 64 bytes");
    }

    @Test
    void rejectedTotal_sumsEveryReason() {
        codec.decode(new byte[0]);
        codec.decode(new byte[2_000]);
        assertEquals(2, codec.decoder.rejected());
        assertEquals(0, codec.decoder.decoded());
    }
}
