package net.smc.core.task;

/**
 * A task: a complex operation a vehicle can perform (move from A to B, follow a path, track an
 * object). A task {@code Explorer} implements its task interface {@code ExplorerI}, marked
 * {@link TaskInterface}. Roles start and stop tasks; policies invoke their operations and react to
 * their events.
 */
public abstract class Task {
    private boolean running;

    /** The task's name: by the paper's naming scheme, the simple name of its class. */
    public String name() {
        return getClass().getSimpleName();
    }

    /** Starts the task (idempotent). */
    public final void start() {
        if (!running) {
            running = true;
            onStart();
        }
    }

    /** Stops the task (idempotent). */
    public final void stop() {
        if (running) {
            running = false;
            onStop();
        }
    }

    public final boolean isRunning() {
        return running;
    }

    /** Called when the task starts; override to begin work. */
    protected void onStart() {
    }

    /** Called when the task stops; override to end work. */
    protected void onStop() {
    }
}
