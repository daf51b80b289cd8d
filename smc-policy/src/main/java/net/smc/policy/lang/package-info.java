/**
 * PonderTalk's front end: {@link net.smc.policy.lang.Lexer} turns text into tokens,
 * {@link net.smc.policy.lang.Parser} turns tokens into an immutable syntax tree of
 * {@link net.smc.policy.lang.Node} records, reporting every syntax error of a unit with its
 * position. Nothing here runs code.
 */
package net.smc.policy.lang;
