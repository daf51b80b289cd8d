/**
 * What a cell is given to talk and to wait, and nothing else: a {@link net.smc.core.transport.Clock}
 * (now, in milliseconds), a {@link net.smc.core.transport.Scheduler} (run this later, on the cell's
 * thread) and a {@link net.smc.core.transport.Transport} (send bytes to an
 * {@link net.smc.core.transport.Address} or broadcast them; a {@link net.smc.core.transport.Receiver}
 * takes what arrives). Protocol code is written against these interfaces only; it never reads a
 * wall clock, sleeps, starts a thread or opens a socket (the cell is sans-IO: {@code doc-files/transport.md}).
 *
 * <p>Implementations: {@code transport.sim} (a virtual clock, a deterministic scheduler and an
 * in-memory network with fault injection, all driven by one thread), {@code transport.real} (the
 * real-time clock and scheduler of a deployed cell, and the serial executor that is its thread) and
 * {@code transport.udp} (Netty UDP, the only package that uses Netty).
 *
 * <p>{@link net.smc.core.transport.udp.StatusResponder} wraps a cell's transport to answer read-only status
 * queries from outside (sent by {@link net.smc.core.transport.udp.StatusClient}, as {@code smc status} does).
 *
 * <p>A simulated pair of cells, in six lines ({@code heard} ends as {@code ["127.0.0.1:4001 says hello"]}):
 * <pre>{@code
 * SimulationScheduler scheduler = new SimulationScheduler();
 * InMemoryNetwork network = new InMemoryNetwork(scheduler, 42);
 * Transport a = network.attach(Address.loopback(4001)), b = network.attach(Address.loopback(4002));
 * List<String> heard = new ArrayList<>();
 * b.setReceiver((from, data) -> heard.add(from + " says " + new String(data)));
 * a.send(b.localAddress(), "hello".getBytes());  scheduler.runUntilIdle(1_000);
 * }</pre>
 *
 * <p>Design decisions and threading rules: <a href="doc-files/transport.md">the transport design note</a>.
 */
package net.smc.core.transport;
