/**
 * The Ponder2-style policy engine of a self-managed cell, embeddable on its own. Start with
 * {@link net.smc.policy.PolicyEngine}: it runs PonderTalk units, holds managed objects in domains,
 * delivers events to obligation policies and checks authorisation policies. The language and its
 * semantics are described in {@code smc-policy/PONDERTALK.md}; {@code lang} parses it, {@code runtime} runs it.
 */
package net.smc.policy;
