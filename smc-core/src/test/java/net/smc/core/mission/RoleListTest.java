package net.smc.core.mission;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import net.smc.core.cell.Missions;

import org.junit.jupiter.api.Test;

/** The mission's role list: a list like any other, and a look-up by name. */
class RoleListTest {
    private static final List<MissionRole> ROLES = Missions.reconnaissance().roles();

    @Test
    void equalsAndHashesAsTheSameRolesInAnyList() {
        RoleList list = RoleList.of(new ArrayList<>(ROLES));
        assertEquals(List.copyOf(ROLES), list);
        assertEquals(list, List.copyOf(ROLES));
        assertEquals(List.copyOf(ROLES).hashCode(), list.hashCode());
        assertEquals(List.copyOf(ROLES).toString(), list.toString());
    }

    @Test
    void findsEveryRoleByName_andNothingElse() {
        RoleList list = RoleList.of(ROLES);
        for (MissionRole r : ROLES) {
            assertSame(r, list.named(r.name()));
        }
        assertNull(list.named("no-such-role"));
        assertNull(list.named(null));
    }

    @Test
    void isUnmodifiable_andRefusesNullRoles() {
        RoleList list = RoleList.of(ROLES);
        assertThrows(UnsupportedOperationException.class, () -> list.add(ROLES.get(0)));
        assertThrows(UnsupportedOperationException.class, () -> list.remove(0));
        NullPointerException e = assertThrows(NullPointerException.class,
                () -> RoleList.of(Arrays.asList(ROLES.get(0), null)));
        assertEquals("role 1 of the mission's roles", e.getMessage());
    }
}
