package net.smc.core.task;

import java.util.Objects;
import net.smc.core.capability.TaskDescription;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Handle;
import net.smc.policy.api.Op;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A task: a complex operation a vehicle can perform (move from A to B, follow a path, track an
 * object). A task {@code Explorer} implements its task interface {@code ExplorerI}, marked
 * {@link TaskInterface}. Roles start and stop tasks; policies invoke their operations and react to
 * their events.
 *
 * <p>A task is a managed object: the {@link Op} selectors of its task interface (and of its class)
 * are its PonderTalk operations, plus {@code name}, {@code start}, {@code stop} and
 * {@code isRunning} from this class. {@link #bind(PolicyEngine)} puts it at {@code root/task/<name>} and
 * makes an event template per {@link TaskEvent} at {@code root/event/<event>}. The task raises an
 * event by calling its own event method, which it implements by handing the arguments to
 * {@link #raise(String, Object...)}:
 *
 * <pre>{@code
 * @TaskInterface("Explorer")
 * public interface ExplorerI {
 *     @Op("moveTo:y:") void moveTo(double x, double y);
 *     @TaskEvent void obstacle(@Attr("x") double x, @Attr("y") double y);
 * }
 * public class Explorer extends Task implements ExplorerI {
 *     public void moveTo(double x, double y) { ... }
 *     public void obstacle(double x, double y) { raise("obstacle", x, y); }
 * }
 * }</pre>
 *
 * <p>Not thread-safe: use a task from its cell's thread, like the cell itself.
 */
public abstract class Task {
    private static final Logger LOG = LoggerFactory.getLogger(Task.class);

    private boolean running;
    private Handle handle;
    private TaskEvents events;
    private long droppedEvents;
    private TaskListener listener;

    /**
     * The task's name: by the paper's naming scheme, the simple name of its class. The capability
     * description, the event binding and {@code root/task/<name>} all use this scheme, so do not
     * override it.
     */
    @Op("name")
    public String name() {
        return getClass().getSimpleName();
    }

    /** Starts the task (idempotent). */
    @Op("start")
    public final void start() {
        if (!running) {
            running = true;
            onStart();
        }
    }

    /** Stops the task (idempotent). */
    @Op("stop")
    public final void stop() {
        if (running) {
            running = false;
            onStop();
        }
    }

    @Op("isRunning")
    public final boolean isRunning() {
        return running;
    }

    /** Called when the task starts; override to begin work. */
    protected void onStart() {
    }

    /** Called when the task stops; override to end work. */
    protected void onStop() {
    }

    /**
     * This task's capability description, by the paper's Table V ({@link TaskDescriber}).
     *
     * @throws TaskDescriptionException when a task interface names another task or an event is malformed
     */
    public final TaskDescription describe() throws TaskDescriptionException {
        return TaskDescriber.describe(getClass());
    }

    /** The task's one managed-object handle, the same object every time (domains and policies compare by identity). */
    public final Handle managed() {
        if (handle == null) {
            handle = PolicyEngine.manage(this);
        }
        return handle;
    }

    /**
     * Makes the task a managed object of {@code cell}: puts it at {@code root/task/<name>} and makes
     * (or reuses) an event template at {@code root/event/<event>} for each of its events. Either all
     * of that happens or, on an error, none of it. Binding again to the same cell does nothing.
     *
     * @throws TaskDescriptionException when the task cannot be described
     * @throws IllegalStateException    when the task is bound to another cell, or a path it needs
     *                                  holds something else (the message names the path)
     */
    public final void bind(PolicyEngine cell) throws TaskDescriptionException {
        Objects.requireNonNull(cell, "cell");
        if (events != null) {
            if (events.cell() == cell) {
                return;
            }
            throw new IllegalStateException("task " + name() + " is already bound to another cell; unbind it first");
        }
        events = TaskEvents.bind(this, cell);
    }

    /** Takes the task out of its cell's {@code root/task} domain; the event templates stay (policies may use them). */
    public final void unbind() {
        if (events != null) {
            events.unbind();
            events = null;
        }
    }

    public final boolean isBound() {
        return events != null;
    }

    /** Sets who is told of each event this task raises while bound (one listener; {@code null}: nobody). */
    public final void listen(TaskListener listener) {
        this.listener = listener;
    }

    /** How many events the task raised while bound to no cell (they went nowhere). */
    public final long droppedEvents() {
        return droppedEvents;
    }

    /**
     * Raises one of the task's events into its cell, with the values in attribute order; Java values
     * convert as {@link PolicyEngine#raise(String, Object...)} converts them. Policies run before this
     * returns. Unbound, the event is counted in {@link #droppedEvents()} and logged at debug level.
     *
     * @return whether the event was delivered ({@code false}: unbound, or the cell reported an error)
     * @throws IllegalArgumentException when the task has no such event or the number of values is wrong
     */
    protected final boolean raise(String event, Object... values) {
        if (events == null) {
            droppedEvents++;
            LOG.debug("task {} raised '{}' while bound to no cell; dropped", name(), event);
            return false;
        }
        boolean delivered = events.raise(event, values);
        if (listener != null) {
            listener.raised(this, event, java.util.Arrays.asList(values.clone()));
        }
        return delivered;
    }
}
