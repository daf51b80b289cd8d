package net.smc.policy.api;

import java.util.Map;
import java.util.Set;

/** A PonderTalk hash (string keys to values) as Java sees it; an {@link Op} parameter of this type takes one. */
@Managed("Hash")
public interface HashValue {

    /** The entries, in insertion order (read-only). */
    Set<Map.Entry<String, Object>> entries();
}
