package net.smc.core.mission;

import java.time.Duration;
import java.time.format.DateTimeParseException;
import java.util.Arrays;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The type a mission class gives a mission parameter ({@code <comTimeout>int</comTimeout>}), and
 * how an instance's text becomes a value of it. Only these six exist so that a parameter means the
 * same in every cell, whatever language its policies use it from.
 */
public enum ParameterType {
    /** A 32-bit integer, decimal ({@code 500}, {@code -3}). */
    INT("int"),
    /** A 64-bit integer, decimal. */
    LONG("long"),
    /** A floating-point number ({@code 2.5}, {@code 1e3}); not NaN, not infinite. */
    DOUBLE("double"),
    /** {@code true} or {@code false}, exactly. */
    BOOLEAN("boolean"),
    /** Any text, trimmed. */
    STRING("string"),
    /** A non-negative time span: a number and a unit ({@code 500ms}, {@code 3s}, {@code 2min}, {@code 1h}) or ISO-8601 ({@code PT3S}). */
    DURATION("duration");

    /** A whole number in ASCII digits. */
    private static final Pattern WHOLE = Pattern.compile("[-+]?[0-9]+");
    /** Decimal notation only: Java's own syntax would also take {@code NaN}, {@code 1d} and hex. */
    private static final Pattern DECIMAL = Pattern.compile("[-+]?(\\d+(\\.\\d*)?|\\.\\d+)([eE][-+]?\\d+)?");
    private static final Pattern SIMPLE_DURATION = Pattern.compile("(\\d{1,18})(ms|s|min|h)");

    private final String xmlName;

    ParameterType(String xmlName) {
        this.xmlName = xmlName;
    }

    /** The name mission classes write: {@code int}, {@code long}, {@code double}, {@code boolean}, {@code string}, {@code duration}. */
    public String xmlName() {
        return xmlName;
    }

    /** The type a mission class names, if it is one of the six. */
    public static Optional<ParameterType> fromXmlName(String name) {
        return Arrays.stream(values()).filter(t -> t.xmlName.equals(name)).findFirst();
    }

    /** The six names, for messages: {@code int, long, double, boolean, string, duration}. */
    static String names() {
        return String.join(", ", Arrays.stream(values()).map(ParameterType::xmlName).toList());
    }

    /**
     * {@code text} when it is a whole number in ASCII digits with an optional sign; Java's parsers
     * take the digits of every script ({@code ١} for 1), which a mission file does not.
     *
     * @throws NumberFormatException otherwise
     */
    static String asciiWhole(String text) {
        if (!WHOLE.matcher(text).matches()) {
            throw new NumberFormatException(text);
        }
        return text;
    }

    /**
     * The value {@code text} denotes: an {@link Integer}, {@link Long}, {@link Double},
     * {@link Boolean}, {@link String} or {@link Duration}.
     *
     * @throws IllegalArgumentException when {@code text} is not a value of this type
     */
    public Object parse(String text) {
        try {
            return switch (this) {
                case INT -> Integer.parseInt(asciiWhole(text));
                case LONG -> Long.parseLong(asciiWhole(text));
                case DOUBLE -> finite(text);
                case BOOLEAN -> bool(text);
                case STRING -> text;
                case DURATION -> duration(text);
            };
        } catch (NumberFormatException | DateTimeParseException | ArithmeticException e) {
            throw new IllegalArgumentException(describe(text));
        }
    }

    private String describe(String text) {
        return "'" + text + "' is not a" + (this == INT ? "n " : " ") + xmlName;
    }

    private Double finite(String text) {
        if (!DECIMAL.matcher(text).matches() || !Double.isFinite(Double.parseDouble(text))) {
            throw new IllegalArgumentException(describe(text));
        }
        return Double.parseDouble(text);
    }

    private Boolean bool(String text) {
        return switch (text) {
            case "true" -> Boolean.TRUE;
            case "false" -> Boolean.FALSE;
            default -> throw new IllegalArgumentException(describe(text));
        };
    }

    private Duration duration(String text) {
        Matcher simple = SIMPLE_DURATION.matcher(text);
        Duration value;
        if (simple.matches()) {
            long amount = Long.parseLong(simple.group(1));
            value = switch (simple.group(2)) {
                case "ms" -> Duration.ofMillis(amount);
                case "s" -> Duration.ofSeconds(amount);
                case "min" -> Duration.ofMinutes(amount);
                default -> Duration.ofHours(amount);
            };
        } else if (text.startsWith("P")) {
            value = Duration.parse(text);
        } else {
            throw new IllegalArgumentException(describe(text) + " (write 500ms, 3s, 2min, 1h or ISO-8601 such as PT3S)");
        }
        if (value.isNegative()) {
            throw new IllegalArgumentException(describe(text) + " (a duration is not negative)");
        }
        return value;
    }
}
