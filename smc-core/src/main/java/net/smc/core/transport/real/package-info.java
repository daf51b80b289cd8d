/**
 * Real time for a deployed cell: {@link net.smc.core.transport.real.SystemClock} (monotonic
 * milliseconds anchored to the epoch), {@link net.smc.core.transport.real.RealTimeScheduler}
 * (timers that fire on the cell's thread) and {@link net.smc.core.transport.real.SerialExecutor}
 * (that thread: one task at a time over a pool that may be shared by many cells).
 *
 * <p>A cell in deployment:
 * <pre>{@code
 * Executor cell = new SerialExecutor(pool);
 * Clock clock = new SystemClock();
 * Scheduler scheduler = new RealTimeScheduler(timer, cell);
 * Transport transport = UdpTransport.open(UdpSettings.defaults().withPort(4001), cell);
 * }</pre>
 * See <a href="../doc-files/transport.md">the transport design note</a>.
 */
package net.smc.core.transport.real;
