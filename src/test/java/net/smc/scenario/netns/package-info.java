/**
 * A network of hosts on one machine for multi-process tests: {@link net.smc.scenario.netns.NetnsLab}
 * puts each host in a Linux network namespace on one bridge (its own namespace too, so the
 * machine's network is never touched), starts processes on the hosts, cuts and heals their links
 * and makes them lose packets (nftables, or iptables' statistic match). {@link net.smc.scenario.netns.LogWatch}
 * waits for what those processes write. Needs root and iproute2; tests check
 * {@code NetnsLab.unavailableReason()} with JUnit assumptions, so elsewhere they are skipped with the reason.
 *
 * <p>{@link net.smc.scenario.netns.TeamOverNetnsTest} runs a team of {@code smc node} processes on a lab:
 * {@link net.smc.scenario.netns.NodeTeam} issues their keys, starts them and reads their logs, and a
 * {@link net.smc.scenario.netns.ViewProbe} on a host of its own collects their status views
 * ({@link net.smc.scenario.netns.NodeView}), since the test's own JVM is outside the lab's network.
 *
 * <pre>{@code
 * Optional<String> reason = NetnsLab.unavailableReason();
 * assumeTrue(reason.isEmpty(), () -> reason.get());
 * try (NetnsLab lab = NetnsLab.create("smcnodes", 6)) {
 *     Process node = lab.start(0, nodeCommand(lab.host(0).address()), dir.resolve("n0.log"));
 *     LogWatch.await(dir.resolve("n0.log"), "node 0 is up", line -> line.contains("started"), Duration.ofSeconds(10));
 *     lab.cut(3);  lab.heal(3);  lab.loss(2, 20);  node.destroyForcibly();
 * }
 * }</pre>
 */
package net.smc.scenario.netns;
