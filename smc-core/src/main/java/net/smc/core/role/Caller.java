package net.smc.core.role;

/**
 * Who invokes a role's external interface from outside the cell: a collaborating role on another
 * vehicle's cell. Inside the receiving role it is the subject
 * {@code root/role/<receiving role>/peers/<role>/<cell>}, so authorisation policies name callers by
 * role ({@code subject: root/role/surveyor/peers/commander}) or by cell.
 *
 * @param cell the calling cell's identifier (a domain name: letters, digits, _)
 * @param role the role the caller acts in
 */
public record Caller(String cell, String role) {
    public Caller {
        RoleNames.check("caller cell", cell);
        RoleNames.checkRole("caller role", role);
    }
}
