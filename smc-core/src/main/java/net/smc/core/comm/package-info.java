/**
 * The cell's communication: the Communication-Manager and the Message-Sender of the paper
 * (section IV-A). Most messages travel connectionless over the cell's
 * {@link net.smc.core.transport.Transport}; the few whose loss would stall the team (role
 * assignment, capability descriptions, policy and invocation exchanges: {@link net.smc.core.comm.CriticalTypes})
 * are acknowledged, retransmitted with exponential backoff and jitter, de-duplicated at the
 * receiver and, when the peer stays silent, reported failed within a bound the settings give.
 *
 * <p>Start at {@link net.smc.core.comm.CommunicationManager}: one per cell, it encodes and sends,
 * decodes what arrives and hands each application message once to the cell's
 * {@link net.smc.core.router.MessageRouter}. Its parts, each small: {@code MessageSender} (the
 * protocol), {@code PendingTable} (outstanding messages), {@code RetryTimer} and {@code Backoff}
 * (when to retransmit), {@code DuplicateWindow} (what a receiver already delivered), {@code Wire}
 * (codec and transport use), {@code IdSource} (message ids), and the counters
 * {@link net.smc.core.comm.SenderCounters} and {@link net.smc.core.comm.CommCounters}.
 *
 * <p>Sans-IO: everything runs on the cell's thread, from the clock, scheduler and transport it is
 * given. Design note: <a href="doc-files/reliable-delivery.md">reliable delivery</a>.
 */
package net.smc.core.comm;
