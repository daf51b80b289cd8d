package net.smc.sim.render;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * What a picture shows besides the world itself: a title, a caption, the robots' role labels,
 * their trajectories, marks and the overlays. Changed by the scenario as the run goes (a mark when
 * a robot stops, a caption per phase) on the simulation's thread, and read by the painter there.
 */
public final class Scene {
    private String title;
    private String caption = "";
    private RoleLabels roles = RoleLabels.NONE;
    private TrajectoryRecorder trajectories;
    private final List<Mark> marks = new ArrayList<>();
    private Overlays overlays = Overlays.defaults();
    private net.smc.sim.map.OccupancyGrid map;

    public Scene(String title) {
        this.title = Objects.requireNonNull(title, "title");
    }

    public Scene title(String title) {
        this.title = Objects.requireNonNull(title, "title");
        return this;
    }

    /** A second line under the title (the phase of the mission, say); "" for none. */
    public Scene caption(String caption) {
        this.caption = Objects.requireNonNull(caption, "caption");
        return this;
    }

    public Scene roles(RoleLabels roles) {
        this.roles = Objects.requireNonNull(roles, "roles");
        return this;
    }

    /** The recorder whose paths are drawn; null for none. */
    public Scene trajectories(TrajectoryRecorder trajectories) {
        this.trajectories = trajectories;
        return this;
    }

    public Scene mark(Mark mark) {
        marks.add(Objects.requireNonNull(mark, "mark"));
        return this;
    }

    /**
     * A map to draw over the arena (a team's hazard map): unknown cells shaded, occupied ones
     * tinted; null for none. Read when painting, so it may keep changing.
     */
    public Scene map(net.smc.sim.map.OccupancyGrid map) {
        this.map = map;
        return this;
    }

    /** The map drawn over the arena, or null. */
    public net.smc.sim.map.OccupancyGrid map() {
        return map;
    }

    public Scene overlays(Overlays overlays) {
        this.overlays = Objects.requireNonNull(overlays, "overlays");
        return this;
    }

    public String title() {
        return title;
    }

    public String caption() {
        return caption;
    }

    public RoleLabels roles() {
        return roles;
    }

    /** The recorder of the paths, or null. */
    public TrajectoryRecorder trajectories() {
        return trajectories;
    }

    public List<Mark> marks() {
        return List.copyOf(marks);
    }

    public Overlays overlays() {
        return overlays;
    }
}
