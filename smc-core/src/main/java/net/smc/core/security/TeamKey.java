package net.smc.core.security;

import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;

/**
 * The team's broadcast key: 32 random bytes a commander makes and hands to each member under its
 * session. The key itself never MACs: HKDF derives a MAC key from it, and a 4-byte id that lets a
 * receiver tell "another team key" from "altered".
 */
final class TeamKey {
    private static final byte[] MAC_INFO = "smc-team-mac-v1".getBytes(StandardCharsets.US_ASCII);
    private static final byte[] ID_INFO = "smc-team-id-v1".getBytes(StandardCharsets.US_ASCII);

    final byte[] key;
    final int id;
    final TruncatedMac mac;
    final Map<String, ReplayWindow> windows = new HashMap<>();

    TeamKey(byte[] key) {
        if (key.length != FrameCodec.TEAM_KEY_BYTES) {
            throw new IllegalArgumentException("a team key is " + FrameCodec.TEAM_KEY_BYTES + " bytes; got " + key.length);
        }
        this.key = key.clone();
        this.id = ByteBuffer.wrap(Hkdf.derive(null, key, ID_INFO, 4)).getInt();
        this.mac = new TruncatedMac(Hkdf.derive(null, key, MAC_INFO, Hkdf.HASH_BYTES));
    }
}
