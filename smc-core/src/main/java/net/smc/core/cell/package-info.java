/**
 * The self-managed cell of one vehicle and the team protocols between cells: start at
 * {@link net.smc.core.cell.Cell} (sans-IO, on any clock, scheduler and transport) or
 * {@link net.smc.core.host.CellHost} (the same cell on Netty UDP with a thread of its own). Seats,
 * identities and priorities are {@link net.smc.core.cell.Slots}'; times are
 * {@link net.smc.core.cell.Timing}'s. The team protocols ({@code TeamProtocol}) are split by
 * responsibility: {@code Recruiter}, {@code Assignee}, {@code Membership}, {@code Supervisor},
 * {@code BackupCommander}, {@code Merge} and {@code Reports}, over a shared {@code TeamContext} and
 * {@code TeamState}. See <a href="doc-files/team-protocols.md">the team-protocols
 * design note</a>.
 */
package net.smc.core.cell;
