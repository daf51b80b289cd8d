package net.smc.core.role;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import net.smc.core.task.Task;

/**
 * The Role-Manager's record of one role on its cell: the role object, which policy files have run
 * (so a second load runs only the missing ones), the tasks it started, and the entries its files
 * added outside {@code root/role/<name>} (so that withdrawing leaves nothing behind).
 */
final class LoadedRole {
    final RoleObject object;
    final Set<String> sources = new LinkedHashSet<>();
    final Map<String, Task> tasks = new LinkedHashMap<>();
    final List<TreeSnapshot.Addition> outside = new ArrayList<>();
    /** The tasks this role bound at {@code root/task} (and so unbinds when withdrawn). */
    final List<Task> bound = new ArrayList<>();
    /** Domains that binding its tasks made ({@code root/task}, {@code root/event}): removed when withdrawn, if empty. */
    final List<TreeSnapshot.Addition> madeDomains = new ArrayList<>();

    LoadedRole(RoleObject object) {
        this.object = object;
    }

    String name() {
        return object.role().name();
    }
}
