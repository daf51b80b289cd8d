/**
 * Tasks: the complex operations a vehicle performs, and how they describe themselves. Start with
 * {@link net.smc.core.task.Task}: a task {@code Explorer} extends it and implements its task
 * interface {@code ExplorerI}, marked {@link net.smc.core.task.TaskInterface}; methods marked
 * {@link net.smc.core.task.TaskEvent} are events (their parameters, named by
 * {@link net.smc.core.task.Attr}, are the attributes), the others operations.
 * {@link net.smc.core.task.TaskDescriber} is the paper's Table V, which turns those annotations into
 * a {@link net.smc.core.capability.TaskDescription}. Binding a task to a cell makes it a managed
 * object: policies invoke its {@code @Op} operations at {@code root/task/<name>} and react to its
 * events at {@code root/event/<event>}.
 *
 * <p>This package and {@code capability} refer to each other on purpose: tasks produce the
 * description records, and the capability module queries the loaded tasks.
 */
package net.smc.core.task;
