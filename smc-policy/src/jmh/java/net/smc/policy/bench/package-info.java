/**
 * JMH benchmarks of the PonderTalk policy engine ({@link net.smc.policy.PolicyEngine}), one class per
 * topic: event delivery ({@link net.smc.policy.bench.EventBench}), the interpreter's inner loop
 * ({@link net.smc.policy.bench.LoopBench}), loading policies ({@link net.smc.policy.bench.LoadBench}),
 * authorisation ({@link net.smc.policy.bench.AuthBench}); plus {@link net.smc.policy.bench.MemoryReport},
 * a plain main that prints retained heap.
 *
 * <p>Run on a small, noisy machine with short iterations and report score ± error, e.g.
 * <pre>
 * ./gradlew :smc-policy:jmh -PjmhArgs="EventBench -f 2 -wi 2 -w 1s -i 3 -r 1s"
 * ./gradlew :smc-policy:jmh -PjmhArgs="EventBench -f 1 -wi 2 -w 1s -i 3 -r 1s -prof gc"
 * java -cp smc-policy/build/classes/java/jmh:smc-policy/build/classes/java/main net.smc.policy.bench.MemoryReport
 * </pre>
 * Every benchmark checks in its setup or teardown (outside the timing) that the policies really
 * did their work and that no error was reported, and fails the run otherwise.
 */
package net.smc.policy.bench;
