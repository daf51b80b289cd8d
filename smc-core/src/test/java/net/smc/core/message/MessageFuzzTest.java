package net.smc.core.message;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * Fuzz targets for the decoder and the reassembler. In the normal test run Jazzer only replays the
 * seeds in {@code MessageFuzzTestInputs/<method>/} (test resources); fuzz for real with
 * {@code ./gradlew :smc-core:test -Pfuzz=1 -Ptests='.*MessageFuzzTest'}. A finding is an exception
 * from the decoder, an internal error, or a decoded datagram that does not re-encode to itself.
 */
class MessageFuzzTest {

    /** One datagram, as raw bytes: from a transport that names no sender, and from one that names one. */
    @FuzzTest(maxDuration = "2m")
    void decode(byte[] datagram) {
        Codec codec = new Codec();
        codec.checkInvariants(datagram, codec.decode(datagram));
        Codec named = new Codec();
        named.checkInvariants(datagram, named.decoder.decode("uav9", datagram, 0, datagram.length), "uav9");
    }

    /**
     * A sequence of fragment frames (few senders and ids, so that they collide) and clock steps fed
     * to one decoder with small bounds, which must hold after every step.
     */
    @FuzzTest(maxDuration = "2m")
    void reassemble(FuzzedDataProvider data) {
        Codec codec = new Codec(new ReassemblySettings(50, WireFormat.MAX_PAYLOAD, 3));
        while (data.remainingBytes() > 0) {
            byte[] datagram;
            if (data.consumeBoolean()) {
                codec.now += data.consumeInt(0, 40);
                continue;
            }
            if (data.consumeBoolean()) {
                datagram = data.consumeBytes(data.consumeInt(0, 1_400));
            } else {
                int count = data.consumeInt(0, 6);
                int total = data.consumeInt(0, 4_000);
                int index = data.consumeInt(0, 6);
                int chunk = Math.max(0, Math.min(Fragmenter.chunkLength(index, Math.max(count, 1), total),
                        1_300)) + data.consumeInt(-1, 1);
                Raw raw = new Raw(WireFormat.FRAGMENT_CODE).u8(data.consumeInt(0, 16)).u16(index).u16(count)
                        .i32(total).raw(data.consumeBytes(Math.max(chunk, 0)));
                raw.sender = new byte[] {(byte) ('a' + data.consumeInt(0, 2))};
                raw.id = data.consumeInt(0, 3);
                datagram = raw.datagram();
            }
            codec.checkInvariants(datagram, codec.decode(datagram));
            if (codec.decoder.reassembliesInProgress() > 3 || codec.decoder.bufferedBytes() > WireFormat.MAX_PAYLOAD
                    || codec.decoder.bufferedBytes() < 0) {
                throw new AssertionError("reassembly bounds broken: " + codec.decoder.reassembliesInProgress()
                        + " reassemblies, " + codec.decoder.bufferedBytes() + " bytes");
            }
        }
    }
}
