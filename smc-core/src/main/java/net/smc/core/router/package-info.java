/**
 * The Message-Router of a cell (the paper, section IV-A): roles and other objects register, as
 * {@link net.smc.core.router.Subscriber}s, for packets by type, by source or both;
 * {@link net.smc.core.router.MessageRouter} aggregates overlapping registrations of one subscriber,
 * keeps an exclusion table for de-registrations inside an aggregate, and checks both on dispatch.
 *
 * <pre>{@code
 * MessageRouter router = new MessageRouter();
 * router.register(relay, MessageType.HEARTBEAT);               // every heartbeat
 * router.register(relay, "uav7");                              // everything from uav7
 * router.deregister(relay, MessageType.HEARTBEAT, "uav3");     // ... but heartbeats from uav3
 * router.dispatch(envelope);                                   // relay receives it at most once
 * }</pre>
 */
package net.smc.core.router;
