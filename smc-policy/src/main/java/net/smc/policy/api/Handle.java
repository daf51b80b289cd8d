package net.smc.policy.api;

import java.util.Set;

/**
 * A managed object as the engine holds it: what sits in domains, has policies attached and answers
 * operations. Java objects with {@link Op} methods get one from {@code PolicyEngine.manage}; domains,
 * event templates and policies are handles of their own.
 */
public interface Handle {

    /** The Java object whose methods implement the operations (the handle itself for built-in kinds). */
    Object impl();

    /** The first path from root to this object ({@code root/a/b}), or {@code null} if it is in no domain tree. */
    String path();

    /** The class name PonderTalk shows ({@code class}, printing). */
    String className();

    /** The selectors it answers, sorted. */
    Set<String> selectors();
}
