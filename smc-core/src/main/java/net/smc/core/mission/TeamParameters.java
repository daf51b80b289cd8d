package net.smc.core.mission;

import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The mission parameters the team protocols read ({@code comTimeout}, {@code failureTimeout},
 * {@code backups}, {@code scheme}) and the rules their values keep. A cell refuses a mission that
 * breaks one ({@code net.smc.core.cell.Timing}, {@code net.smc.core.cell.Scheme}), and the loader
 * reports it at the parameter, so that a mission that validates also runs.
 */
public final class TeamParameters {
    /** The most backup commanders a team keeps. */
    public static final int MAX_BACKUPS = 8;

    /** A rule a parameter's value breaks: the parameter it is reported at and the message. */
    public record Problem(String parameter, String message) {
    }

    private TeamParameters() {
    }

    /**
     * What is wrong with the protocols' times and backups, if anything: {@code comTimeout} at least
     * 1 ms, {@code failureTimeout} at least three times it, {@code backups} 0 to {@value #MAX_BACKUPS}.
     */
    public static Optional<Problem> timing(long comTimeoutMillis, long failureTimeoutMillis, long backups) {
        if (comTimeoutMillis < 1) {
            return Optional.of(new Problem("comTimeout", "comTimeout is " + comTimeoutMillis + " ms; it must be at least 1 ms"));
        }
        if (comTimeoutMillis > Long.MAX_VALUE / 3 || failureTimeoutMillis < 3 * comTimeoutMillis) {
            return Optional.of(new Problem("failureTimeout", "failureTimeout is " + failureTimeoutMillis + " ms; it must be"
                    + " at least three times comTimeout (" + comTimeoutMillis + " ms), or one lost heartbeat would look like a failure"));
        }
        if (backups < 0 || backups > MAX_BACKUPS) {
            return Optional.of(new Problem("backups", "backups is " + backups + "; it must be 0 to " + MAX_BACKUPS));
        }
        return Optional.empty();
    }

    /**
     * The scheme a {@code scheme} parameter names, as {@code distributed} or {@code centralised}
     * ({@code centralized} too, in any case).
     *
     * @throws IllegalArgumentException naming the value and the accepted ones
     */
    public static String scheme(String text) {
        return switch (text.trim().toLowerCase(Locale.ROOT)) {
            case "distributed" -> "distributed";
            case "centralised", "centralized" -> "centralised";
            default -> throw new IllegalArgumentException("scheme '" + text
                    + "' is not known; it must be 'distributed' or 'centralised'");
        };
    }

    /**
     * The types a mission class may declare team parameter {@code name} with, as mission classes
     * write them ({@code int}, {@code duration}); empty for a parameter the protocols do not read.
     */
    public static List<String> typesOf(String name) {
        return switch (name) {
            case "comTimeout", "failureTimeout" -> List.of("int", "long", "duration");
            case "backups" -> List.of("int", "long");
            case "scheme" -> List.of("string");
            default -> List.of();
        };
    }

    /**
     * A count parameter's value ({@code backups}): a whole number.
     *
     * @throws IllegalArgumentException naming the parameter when the value is not one
     */
    public static long count(String name, Object value) {
        if (value instanceof Integer || value instanceof Long) {
            return ((Number) value).longValue();
        }
        throw new IllegalArgumentException("mission parameter '" + name + "' is " + value + "; it must be a whole number");
    }

    /**
     * A parameter's value as milliseconds: an int is taken for ms, a duration converted.
     *
     * @throws IllegalArgumentException naming the parameter when the value is neither
     */
    public static long millis(String name, Object value) {
        if (value instanceof Number n) {
            return n.longValue();
        }
        if (value instanceof Duration d) {
            try {
                return d.toMillis();
            } catch (ArithmeticException e) {
                return d.isNegative() ? Long.MIN_VALUE : Long.MAX_VALUE;
            }
        }
        throw new IllegalArgumentException("mission parameter '" + name + "' is " + value + "; it must be a number of ms");
    }
}
