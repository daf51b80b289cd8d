package net.smc.core.task;

import net.smc.policy.api.Op;

/** The example task interface of the paper's section IV-B: operations, and events marked {@link TaskEvent}. */
@TaskInterface("Explorer")
public interface ExplorerI {
    @Op("moveTo:y:")
    void moveTo(double x, double y);

    @Op("explore:")
    void explore(String area);

    @Op("position")
    String position();

    @TaskEvent
    void obstacle(@Attr("x") double x, @Attr("y") double y);

    @TaskEvent
    void arrived(@Attr("area") String area);

    /** Static: not part of what the task offers, so not in its description. */
    static String unit() {
        return "metre";
    }
}
