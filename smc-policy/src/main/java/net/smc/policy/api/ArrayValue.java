package net.smc.policy.api;

import java.util.List;

/** A PonderTalk array ({@code #(1 2 3)}) as Java sees it; an {@link Op} parameter of this type takes one. */
@Managed("Array")
public interface ArrayValue {

    /** The elements, in order (read-only). */
    List<Object> items();
}
