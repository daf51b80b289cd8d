package net.smc.policy.api;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Exposes a Java method or constructor as a PonderTalk operation with the given selector: unary
 * ({@code size}), binary ({@code +}, one argument) or keyword ({@code at:put:}, one argument per
 * colon). Instance methods (also those declared on implemented interfaces; the class wins) become
 * the object's operations; constructors and static methods become
 * its factory's. A leading parameter of type {@code net.smc.policy.runtime.CallContext} is hidden from PonderTalk and
 * receives the call's context. Arity is checked when the class is first used.
 *
 * <pre>{@code
 * public class Counter {
 *     private int count;
 *     @Op("create") public Counter() { }
 *     @Op("add:") public void add(int n) { count += n; }   // answers the receiver
 *     @Op("count") public int count() { return count; }
 * }
 * }</pre>
 */
@Retention(RetentionPolicy.RUNTIME)
@Target({ElementType.METHOD, ElementType.CONSTRUCTOR})
public @interface Op {
    /** The selector, e.g. {@code "at:put:"}. */
    String value();
}
