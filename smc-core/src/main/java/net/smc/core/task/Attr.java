package net.smc.core.task;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Names an attribute of a task event: {@code @TaskEvent void obstacle(@Attr("x") double x, @Attr("y") double y)}.
 *
 * <p>Why it exists: obligation policies bind their block parameters to event attributes by name
 * ({@code [:x :y | ...]}), but a class file keeps parameter names only when javac ran with
 * {@code -parameters}, which this build does not pass. So the name is written here. Where the
 * class was compiled with {@code -parameters} and a parameter has no {@code @Attr}, its source name
 * is used; otherwise a missing name is an error when the task is described. The name must be a
 * PonderTalk identifier (a letter, then letters, digits or {@code _}).
 */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.PARAMETER)
public @interface Attr {
    /** The attribute's name, e.g. {@code "x"}. */
    String value();
}
