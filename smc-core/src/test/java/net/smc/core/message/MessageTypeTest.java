package net.smc.core.message;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

class MessageTypeTest {

    @Test
    void codes_areTheDocumentedOnes() {
        // Codes are wire format: this table changes only by adding a type with a new code.
        Map<MessageType, Integer> expected = new LinkedHashMap<>();
        int code = 1;
        for (String name : new String[] {"DISCOVERY", "DISCOVERY_REPLY", "CAPABILITY_REQUEST", "CAPABILITY_REPLY",
                "ROLE_ASSIGNMENT", "ASSIGNMENT_RESPONSE", "POLICY_REQUEST", "POLICY_REPLY", "HEARTBEAT", "ACK",
                "ROLE_EVENT", "INVOCATION", "INVOCATION_RESULT", "LEAVE", "STATUS", "ACKS", "ROSTER", "SUBTREE_REPORT", "CELL_REQUEST", "ECHO", "WITHDRAWAL"}) {
            expected.put(MessageType.valueOf(name), code++);
        }
        Map<MessageType, Integer> actual = new LinkedHashMap<>();
        for (MessageType t : MessageType.values()) {
            actual.put(t, t.code());
        }
        assertEquals(expected, actual);
    }

    @Test
    void fromCode_findsEveryType() {
        for (MessageType t : MessageType.values()) {
            assertEquals(t, MessageType.fromCode(t.code()));
        }
    }

    @Test
    void fromCode_refusesReservedAndUnassignedCodes() {
        for (int code : new int[] {0x00, 0x16, WireFormat.FRAGMENT_CODE, -1, 256}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> MessageType.fromCode(code));
            assertEquals("message type code " + code + " is not assigned; assigned codes are 1 to 21", e.getMessage());
        }
    }
}
