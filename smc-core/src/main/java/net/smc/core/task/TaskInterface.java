package net.smc.core.task;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Marks an interface as a task interface and names its task: {@code @TaskInterface("Explorer")}
 * on {@code ExplorerI}, implemented by the task {@code Explorer} (the paper's naming scheme). Its
 * methods are the task's operations, or its events where marked {@link TaskEvent}. An operation
 * that policies may invoke also carries {@code net.smc.policy.api.Op} with its PonderTalk
 * selector ({@code @Op("moveTo:y:")}). See {@link TaskDescriber} for how the annotations are read.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.TYPE)
public @interface TaskInterface {
    /** The name of the task that implements the interface. */
    String value();
}
