/**
 * PonderTalk's run time: the {@link net.smc.policy.runtime.Interpreter} (which compiles the syntax
 * tree into executable nodes), values ({@link net.smc.policy.runtime.PArray},
 * {@link net.smc.policy.runtime.PHash}, {@link net.smc.policy.runtime.Block}, numbers, strings,
 * booleans, nil), managed objects and their dispatch tables (built once per class from
 * {@link net.smc.policy.api.Op} annotations), domains, event templates, obligation and
 * authorisation policies and the {@code Authoriser} that decides by domain nesting.
 */
package net.smc.policy.runtime;
