/**
 * Roles and the Role-Manager (the paper's sections II-B.2 and IV-A). A {@link net.smc.core.role.Role}
 * is an immutable description: its role-mission and authorisation policy files, its tasks, the
 * roles it manages, and its {@link net.smc.core.role.ExternalInterface} and
 * {@link net.smc.core.role.LocalInterface}. The {@link net.smc.core.role.RoleManager} loads it onto a
 * cell as the domain {@code root/role/<name>} (all or nothing, once) and withdraws it without a
 * trace; the {@link net.smc.core.role.ExternalGateway} lets other vehicles' roles use its external
 * interface under its authorisation policies. The convention that role policy files follow is in
 * {@code policies/README.md}.
 */
package net.smc.core.role;
