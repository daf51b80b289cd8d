package net.smc.core.comm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;

import org.junit.jupiter.api.Test;

import net.smc.core.message.MessageType;

class CriticalTypesTest {

    @Test
    void default_holdsTheRequestReplyExchanges_andNotDiscoveryOrHeartbeats() {
        assertEquals(EnumSet.of(MessageType.ROLE_ASSIGNMENT, MessageType.ASSIGNMENT_RESPONSE,
                MessageType.CAPABILITY_REQUEST, MessageType.CAPABILITY_REPLY, MessageType.POLICY_REQUEST,
                MessageType.POLICY_REPLY, MessageType.INVOCATION, MessageType.INVOCATION_RESULT, MessageType.ROLE_EVENT,
                MessageType.CELL_REQUEST),
                EnumSet.copyOf(CriticalTypes.DEFAULT.types()));
        assertFalse(CriticalTypes.DEFAULT.contains(MessageType.HEARTBEAT));
        assertFalse(CriticalTypes.DEFAULT.contains(MessageType.DISCOVERY));
        assertFalse(CriticalTypes.DEFAULT.contains(MessageType.SUBTREE_REPORT));
    }

    @Test
    void ack_cannotBeCritical() {
        var e = assertThrows(IllegalArgumentException.class, () -> CriticalTypes.DEFAULT.with(MessageType.ACK));
        assertTrue(e.getMessage().startsWith("ACK cannot be a critical type"), e.getMessage());
    }

    @Test
    void withAndWithout_changeTheSet() {
        CriticalTypes c = CriticalTypes.none().with(MessageType.STATUS);
        assertTrue(c.contains(MessageType.STATUS));
        assertFalse(c.without(MessageType.STATUS).contains(MessageType.STATUS));
    }
}
