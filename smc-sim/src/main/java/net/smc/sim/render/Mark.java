package net.smc.sim.render;

import java.util.Objects;

/** Something a scenario marks on the picture at a place in the world (metres). */
public sealed interface Mark {

    /** Its label, drawn beside it ("" for none). */
    String label();

    /** A red X: where something stopped or failed. */
    record Cross(double x, double y, String label) implements Mark {
        public Cross {
            Objects.requireNonNull(label, "label");
        }
    }

    /** A dashed circle of {@code radius} metres: a zone a robot was told to keep out of. */
    record AvoidedZone(double x, double y, double radius, String label) implements Mark {
        public AvoidedZone {
            Objects.requireNonNull(label, "label");
            if (!(radius > 0)) {
                throw new IllegalArgumentException("avoided zone '" + label + "' has radius " + radius + " m; it must be above 0");
            }
        }
    }

    /** A magenta diamond: a hazard as a team reported it (a hazard map's entry). */
    record Found(double x, double y, String label) implements Mark {
        public Found {
            Objects.requireNonNull(label, "label");
        }
    }
}
