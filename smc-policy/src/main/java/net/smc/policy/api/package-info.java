/**
 * What a Java class needs to become a PonderTalk managed object, with no dependency on the
 * engine's inside: {@link net.smc.policy.api.Op} (an operation), {@link net.smc.policy.api.Managed}
 * (the class's PonderTalk name) and {@link net.smc.policy.api.PonderError} (an error a policy sees).
 * Other modules import these, not {@code net.smc.policy.runtime}.
 */
package net.smc.policy.api;
