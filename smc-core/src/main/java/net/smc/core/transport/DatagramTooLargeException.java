package net.smc.core.transport;

/**
 * A cell tried to send more than {@link Transport#MAX_DATAGRAM_BYTES} bytes in one datagram. It is
 * refused rather than fragmented: a lost fragment loses the whole datagram, and a radio link drops
 * large frames first. A protocol that needs more splits its data itself.
 */
public final class DatagramTooLargeException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    private final int length;

    private DatagramTooLargeException(String message, int length) {
        super(message);
        this.length = length;
    }

    /** The size of the refused datagram, in bytes. */
    public int length() {
        return length;
    }

    /**
     * Throws when {@code length} is over the limit.
     *
     * @param from the sending cell
     * @param to   the destination, or null for a broadcast
     */
    public static void check(Address from, Address to, int length) {
        if (length > Transport.MAX_DATAGRAM_BYTES) {
            throw new DatagramTooLargeException("datagram of " + length + " bytes from " + from + " to "
                    + (to == null ? "broadcast" : to.toString()) + " refused: a datagram may carry at most "
                    + Transport.MAX_DATAGRAM_BYTES + " bytes", length);
        }
    }
}
