/**
 * Capability descriptions (the paper's section IV-B): what a vehicle can do. Start with
 * {@link net.smc.core.task.Capabilities}, the Capability module of one vehicle: it holds the
 * vehicle's resources and loaded tasks and prepares, on request, the full
 * {@link net.smc.core.capability.CapabilityDescription} (every task's operations and events, from
 * Table V) and its compact {@link net.smc.core.capability.CapabilitySummary}.
 * {@link net.smc.core.capability.CapabilityCodec} puts both on the wire;
 * {@link net.smc.core.capability.CapabilityRequirement} says whether a vehicle can take a role.
 *
 * <pre>{@code
 * Capabilities caps = new Capabilities("uav7", Set.of("motion", "video"));
 * caps.load(new Explorer());                                     // Explorer implements ExplorerI
 * byte[] reply = CapabilityCodec.STANDARD.encode(caps.summary()); // a discovery reply's payload
 * boolean surveyor = CapabilityRequirement.of(Set.of("video"), Set.of("Explorer")).isMetBy(caps.summary());
 * }</pre>
 */
package net.smc.core.capability;

