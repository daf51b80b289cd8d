/**
 * Hosting a vehicle's cell on a real network: {@link net.smc.core.host.CellHost} runs one sans-IO
 * {@code net.smc.core.cell.Cell} over Netty UDP, with a wall clock, one executor thread and the
 * status responder. The cell package itself stays free of threads, sockets and wall clocks.
 */
package net.smc.core.host;
