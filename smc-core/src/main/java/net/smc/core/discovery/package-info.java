/**
 * The commander-side discovery object that the paper's role-assignment policy (Table I) talks to,
 * {@code root/discovery}: {@link net.smc.core.discovery.DiscoveryObject} checks a newly discovered
 * vehicle's capability summary and credential, and asks for its full capability description. The
 * credential check ({@link net.smc.core.discovery.CredentialCheck}) and the request itself
 * ({@link net.smc.core.discovery.DiscoveryActions}) are pluggable: authentication and the team
 * protocols provide them.
 */
package net.smc.core.discovery;
