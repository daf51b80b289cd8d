package net.smc.core.message;

/**
 * Bounds of the fragment reassembler, which holds pieces of messages from peers it cannot trust to
 * finish them.
 *
 * @param expiryMillis how long a reassembly may wait for its missing fragments, counted from its
 *                     first fragment, in milliseconds of the injected clock (at least 1)
 * @param maxBufferedBytes the most fragment bytes held at once over all reassemblies; at least
 *                         {@link WireFormat#MAX_PAYLOAD}, so that any one message fits
 * @param maxReassemblies the most messages reassembled at once (at least 1)
 */
public record ReassemblySettings(long expiryMillis, int maxBufferedBytes, int maxReassemblies) {
    /** 5 s, 1 MiB, 64 messages. */
    public static final ReassemblySettings DEFAULTS = new ReassemblySettings(5_000, 1 << 20, 64);

    public ReassemblySettings {
        if (expiryMillis < 1) {
            throw new IllegalArgumentException("expiryMillis is " + expiryMillis + "; it must be 1 ms or more");
        }
        if (maxBufferedBytes < WireFormat.MAX_PAYLOAD) {
            throw new IllegalArgumentException("maxBufferedBytes is " + maxBufferedBytes + "; it must be at least "
                    + WireFormat.MAX_PAYLOAD + " (the largest message)");
        }
        if (maxReassemblies < 1) {
            throw new IllegalArgumentException("maxReassemblies is " + maxReassemblies + "; it must be 1 or more");
        }
    }
}
