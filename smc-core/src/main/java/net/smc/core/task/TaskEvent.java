package net.smc.core.task;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Marks a method of a task interface as an event the task raises rather than an operation it
 * offers; the method's parameters are the event's attributes, each named by {@link Attr}. The task
 * implements the method by raising the event ({@code raise("obstacle", x, y)}), so calling it is
 * how the task raises it; bound to a cell, the event's template is {@code root/event/<method name>}.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.METHOD)
public @interface TaskEvent {
}
