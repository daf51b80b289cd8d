package net.smc.policy.lang;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * The syntax trees of small units, shared by the cells of one process that run the same text: a
 * simulated team of 1,000 vehicles boots 1,000 engines on one boot file and loads each role's
 * policies in every vehicle that takes it, and each would otherwise parse the same text twice (to
 * check it, then statement by statement to run it). Each cell still runs every statement itself;
 * only the parse is shared, so what runs, and every effect and diagnostic of running it, is the same.
 *
 * <p>Kept: units of at most {@code maxChars} characters that parsed without errors and included no
 * file (an include's text can differ between cells and over time); at most {@code maxUnits} of them,
 * the least recently used forgotten first. The key is the unit's source name and its whole text.
 * Trees are immutable ({@link Node}), so cells on different threads can share them. Thread-safe.
 * A deployed cell (one per process) has no use for it and needs none.
 */
public final class ParsedUnits {
    private final int maxUnits;
    private final int maxChars;
    private final Map<String, Unit> units;

    /**
     * @param maxUnits how many units are kept, 1 or more
     * @param maxChars the longest text kept, in characters, 1 or more
     */
    public ParsedUnits(int maxUnits, int maxChars) {
        if (maxUnits < 1 || maxChars < 1) {
            throw new IllegalArgumentException("parsed units: at most " + maxUnits + " units of " + maxChars
                    + " characters; both must be 1 or more");
        }
        this.maxUnits = maxUnits;
        this.maxChars = maxChars;
        this.units = new LinkedHashMap<>(16, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<String, Unit> eldest) {
                return size() > ParsedUnits.this.maxUnits;
            }
        };
    }

    /** The kept unit of this source and text, whose statements are given from its tree; or null. */
    public synchronized Unit find(String source, String text) {
        return text.length() > maxChars ? null : units.get(key(source, text));
    }

    /**
     * Keeps {@code checked}, parsed from {@code text} by {@link Parser#parse(String, String, IncludeResolver)},
     * if it is small, has no errors and {@code includedAny} is false; answers the unit to run: the kept
     * one, or {@code checked} itself when it is not kept.
     */
    public Unit keep(Unit checked, String text, boolean includedAny) {
        Objects.requireNonNull(checked, "checked");
        if (includedAny || checked.hasErrors() || text.length() > maxChars) {
            return checked;
        }
        Unit parsed = new Unit(checked.source(), List.copyOf(checked.statements()));
        synchronized (this) {
            units.put(key(checked.source(), text), parsed);
        }
        return parsed;
    }

    /** How many units are kept. */
    public synchronized int size() {
        return units.size();
    }

    private static String key(String source, String text) {
        return source + '\0' + text;
    }
}
