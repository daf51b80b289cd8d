package net.smc.core.transport.udp;

/**
 * What a {@link UdpTransport} did (a snapshot). Every datagram that arrived is either
 * {@code delivered} or counted under one of the {@code dropped} reasons.
 *
 * @param sent                  unicast datagrams handed to the kernel
 * @param broadcastsSent        broadcast datagrams handed to the kernel
 * @param sendFailures          sends the kernel or Netty reported as failed (logged at debug)
 * @param refusedOversize       sends refused for being larger than the limit (the caller got an exception)
 * @param delivered             datagrams handed to the receiver
 * @param ownBroadcastsFiltered the cell's own broadcasts that came back to it and were discarded
 * @param droppedOversize       datagrams that arrived larger than the limit
 * @param droppedNoReceiver     datagrams that arrived before a receiver was set
 * @param droppedClosed         datagrams that reached the cell's thread after close
 * @param droppedRejected       datagrams the cell's executor refused (it was shut down)
 * @param droppedBacklog        non-urgent datagrams dropped because too many already waited for the cell
 *                              ({@link UdpTransport#setUrgent})
 */
public record UdpCounters(long sent, long broadcastsSent, long sendFailures, long refusedOversize, long delivered,
                          long ownBroadcastsFiltered, long droppedOversize, long droppedNoReceiver,
                          long droppedClosed, long droppedRejected, long droppedBacklog) {
}
