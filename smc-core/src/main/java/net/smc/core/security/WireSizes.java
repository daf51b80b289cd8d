package net.smc.core.security;

import java.nio.charset.StandardCharsets;

/**
 * The lengths of this layer's datagrams on the wire, from the names they carry, for a model of the
 * traffic that does not run the layer: a simulated radio charges each datagram's air time by the
 * length the real datagram would have (the wire forms are in the security design note).
 *
 * <pre>{@code
 * int air = WireSizes.signed("uav-1", "rescue", payload.length);   // a discovery as broadcast
 * int hello = WireSizes.hello("uav-1", "rescue", "uav-2");          // one step of a handshake
 * }</pre>
 */
public final class WireSizes {
    private WireSizes() {
    }

    /** A credential for {@code vehicle} in {@code mission}: 123 bytes and the two names. */
    public static int credential(String vehicle, String mission) {
        return CredentialCodec.FIXED_BYTES + utf8(vehicle) + utf8(mission);
    }

    /** A {@code SIGNED} datagram of {@code payload} bytes from {@code vehicle}, its credential attached. */
    public static int signed(String vehicle, String mission, int payload) {
        return FrameCodec.signedOverhead(credential(vehicle, mission)) + payload;
    }

    /** A {@code PAIR_MAC} datagram of {@code payload} bytes from {@code vehicle}, under a session. */
    public static int pairMac(String vehicle, int payload) {
        return FrameCodec.pairOverhead(utf8(vehicle)) + payload;
    }

    /** A {@code HELLO} (one step of a handshake) from {@code vehicle} to {@code recipient}. */
    public static int hello(String vehicle, String mission, String recipient) {
        return FrameCodec.signedOverhead(credential(vehicle, mission)) + 1 + utf8(recipient) + 2 * Ephemeral.BYTES;
    }

    private static int utf8(String name) {
        return name.getBytes(StandardCharsets.UTF_8).length;
    }
}
