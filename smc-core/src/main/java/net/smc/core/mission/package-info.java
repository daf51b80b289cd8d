/**
 * Mission specifications, the paper's levels 2 and 3: a mission class (XML) names the roles, what
 * each manages and needs of a vehicle, which roles may share a vehicle, and the mission's typed
 * parameters; a mission instance (XML) instantiates a class with parameter values, each role's
 * minimal and reasonably-optimal cardinality, and the policy URIs that give each role its
 * behaviour.
 *
 * <p>Start at {@link net.smc.core.mission.MissionLoader}: it reads both files (with the Stax
 * parser of Jackson's XML module, keeping each element's line and column), checks them, resolves
 * the policies in a {@link net.smc.policy.api.PolicyRepository} and returns an immutable
 * {@link net.smc.core.mission.Mission}, or a {@link net.smc.core.mission.MissionException} listing
 * every {@link net.smc.core.mission.MissionError} as {@code FILE:LINE:COL: <element>: message}.
 * Inside, one class per phase: {@link net.smc.core.xml.XmlReader} (text to a positioned tree), {@code ClassReader}
 * (with {@code ConstraintsReader}) and {@code InstanceReader} (structure), {@code ClassRules} and
 * {@code InstanceRules} (the names and numbers make sense together), {@code PolicyCheck} (URIs
 * resolve and parse). The file format is in {@code missions/README.md}, with XSDs beside it.
 */
package net.smc.core.mission;
