package net.smc.core.role;

import java.util.ArrayList;
import java.util.List;
import net.smc.core.task.Task;
import net.smc.policy.api.Op;

/** A test task: records where it was sent and how often it started and stopped. */
class Explorer extends Task {
    final List<Object> visited = new ArrayList<>();
    int starts;
    int stops;

    @Op("goTo:")
    public void goTo(Object where) {
        visited.add(where);
    }

    @Op("visited")
    public int visitedCount() {
        return visited.size();
    }

    @Override
    protected void onStart() {
        starts++;
    }

    @Override
    protected void onStop() {
        stops++;
    }
}
