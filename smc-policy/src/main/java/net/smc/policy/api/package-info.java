/**
 * The engine's public types, with no dependency on its inside ({@code net.smc.policy.runtime}):
 * what makes a Java class a PonderTalk managed object ({@link net.smc.policy.api.Op},
 * {@link net.smc.policy.api.Managed}, {@link net.smc.policy.api.PonderError}, the value {@link net.smc.policy.api.Nil}) and what configures
 * and reports a {@code net.smc.policy.PolicyEngine} ({@link net.smc.policy.api.AuthMode},
 * {@link net.smc.policy.api.Limits}, {@link net.smc.policy.api.PolicyRepository}, {@link net.smc.policy.api.TimerScheduler},
 * {@link net.smc.policy.api.Diagnostic}). A package of its own rather than the module's top package:
 * the runtime uses these types and the top package's facade uses the runtime, so putting them at
 * the top would make the facade and the runtime use each other.
 */
package net.smc.policy.api;
