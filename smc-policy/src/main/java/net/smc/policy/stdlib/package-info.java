/**
 * The standard objects of Ponder2's release, loadable with {@code root load: "Name"}: {@code Timer}
 * (on the cell's injected clock and scheduler), {@code EventForwarder}, {@code PonderTalk},
 * {@code Semaphore}, {@code DynamicString}, {@code CsvHash}, {@code SampleObject}, and the XML
 * values that {@code "..." asXML} makes. {@link net.smc.policy.stdlib.StandardObjects} is the one
 * place they are registered; smc-policy/PONDERTALK.md section 6.1 describes their behaviour.
 */
package net.smc.policy.stdlib;
