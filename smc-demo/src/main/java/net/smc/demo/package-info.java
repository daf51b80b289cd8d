/**
 * The {@code smc} command: runs PonderTalk files in a self-managed cell's policy engine
 * ({@link net.smc.policy.PolicyEngine}), offers an interactive shell on one cell, and runs a vehicle's whole
 * cell as a network node.
 *
 * <p>Start at {@link net.smc.demo.Main}, the picocli root command; its subcommands are
 * {@code RunCommand} ({@code smc run FILE.p2 ...}) and {@code ShellCommand}
 * ({@code smc shell [FILE.p2 ...]}); {@code NodeCommand} ({@code smc node ...}) runs one vehicle's cell
 * on the network until the process ends (its files read by {@code NodeFiles}, its output written by
 * {@code NodeLog}, its end signalled by {@code StopSignal}); {@code StatusCommand}
 * ({@code smc status --node ADDR:PORT}) asks a running node for its view. {@code run} and {@code shell} set up their cell through {@code CommandCell} and
 * {@code CellOptions}, and run it on a thread with a large stack ({@code LargeStack}). The
 * commands never touch {@code System.in/out/err} or call {@code System.exit}: the streams come in
 * an {@code Io}, and only {@code Main.main} ends the process, so tests drive the commands in-process.
 *
 * <pre>{@code
 * ./gradlew :smc-demo:installDist
 * smc-demo/build/install/smc/bin/smc run boot.p2 more.p2
 * smc-demo/build/install/smc/bin/smc shell --auth deny boot.p2
 * }</pre>
 */
package net.smc.demo;
