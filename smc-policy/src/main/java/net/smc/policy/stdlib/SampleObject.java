package net.smc.policy.stdlib;

import java.util.LinkedHashMap;
import java.util.Map;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.api.PonderError;

/**
 * Ponder2's example managed object: a store of values by name. {@code at: name put: value}
 * (answers the value), {@code at: name} (a missing name: {@code SampleObject: no value for 'x'}).
 */
@Managed("SampleObject")
final class SampleObject {
    private final Map<String, Object> values = new LinkedHashMap<>();

    @Op("create")
    SampleObject() {
    }

    @Op("at:put:")
    Object atPut(String name, Object value) {
        values.put(name, value);
        return value;
    }

    @Op("at:")
    Object at(String name) {
        Object v = values.get(name);
        if (v == null) {
            throw new PonderError("SampleObject: no value for '" + name + "'");
        }
        return v;
    }
}
