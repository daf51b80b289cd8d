/**
 * Real UDP over Netty, the only package of the project that uses Netty:
 * {@link net.smc.core.transport.udp.UdpTransport} (a cell's endpoint: its own unicast channel and
 * a shared broadcast channel), {@link net.smc.core.transport.udp.UdpSettings} (where it binds and
 * broadcasts), {@link net.smc.core.transport.udp.UdpEventLoop} (the I/O threads, shareable by many
 * cells) and {@link net.smc.core.transport.udp.UdpCounters}. No Netty type appears in the public
 * API, so the rest of the project needs no Netty on its compile path.
 *
 * <p>See <a href="../doc-files/transport.md">the transport design note</a>.
 */
package net.smc.core.transport.udp;
