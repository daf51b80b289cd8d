package net.smc.core.mission;

import java.time.Duration;
import java.util.Objects;

/**
 * One mission parameter of an instance: the name and type its class declares and the value the
 * instance gives. Mission parameters (timeouts, say) are shared by every role of the team.
 *
 * @param name  the parameter's name ({@code failureTimeout})
 * @param type  its declared type
 * @param value its value, of the Java type {@link ParameterType#parse} gives for {@code type}
 */
public record Parameter(String name, ParameterType type, Object value) {

    public Parameter {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(type, "type");
        Objects.requireNonNull(value, "value");
        Class<?> expected = switch (type) {
            case INT -> Integer.class;
            case LONG -> Long.class;
            case DOUBLE -> Double.class;
            case BOOLEAN -> Boolean.class;
            case STRING -> String.class;
            case DURATION -> Duration.class;
        };
        if (!expected.isInstance(value)) {
            throw new IllegalArgumentException("parameter '" + name + "' of type " + type.xmlName() + " has "
                    + withArticle(value.getClass().getSimpleName()) + " value; it must be " + withArticle(expected.getSimpleName()));
        }
    }

    private static String withArticle(String name) {
        return ("AEIOU".indexOf(name.charAt(0)) >= 0 ? "an " : "a ") + name;
    }

    public int asInt() {
        return (Integer) as(ParameterType.INT);
    }

    /** The value as a long; an {@code int} parameter widens. */
    public long asLong() {
        return type == ParameterType.INT ? (Integer) value : (Long) as(ParameterType.LONG);
    }

    /** The value as a double; {@code int} and {@code long} parameters widen. */
    public double asDouble() {
        return value instanceof Number number && type != ParameterType.DOUBLE ? number.doubleValue()
                : (Double) as(ParameterType.DOUBLE);
    }

    public boolean asBoolean() {
        return (Boolean) as(ParameterType.BOOLEAN);
    }

    public String asString() {
        return (String) as(ParameterType.STRING);
    }

    public Duration asDuration() {
        return (Duration) as(ParameterType.DURATION);
    }

    private Object as(ParameterType wanted) {
        if (type != wanted) {
            throw new IllegalStateException("parameter '" + name + "' is " + type.xmlName() + ", not " + wanted.xmlName());
        }
        return value;
    }

    /** The value as a mission file writes it ({@code 500}, {@code PT3S}). */
    public String text() {
        return value.toString();
    }
}
