package net.smc.policy.stdlib;

import java.util.ArrayList;
import java.util.List;
import net.smc.policy.runtime.Block;
import net.smc.policy.runtime.CallContext;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import net.smc.policy.runtime.PArray;
import net.smc.policy.runtime.PHash;
import net.smc.policy.api.PonderError;

/**
 * Ponder2's comma-separated table: {@code create: "file.csv"} reads the file (found as
 * {@code read:} finds files); its first line holds the column titles. {@code titles} answers them;
 * {@code do: [:row | ]} calls the block with each row as a hash title to value, where an empty
 * field repeats the value above it (as Ponder2); {@code size} and {@code at: i} (0-based, a row as
 * an array) as an array's. Fields are split at every comma (no quoting, as Ponder2); short rows are
 * padded with empty fields.
 */
@Managed("CsvHash")
final class CsvHash {
    private final List<String> titles;
    private final List<List<String>> rows = new ArrayList<>();

    @Op("create:")
    CsvHash(CallContext ctx, String file) {
        String text = ctx.runtime().readText(file, ctx.pos() == null ? null : ctx.pos().source());
        String[] lines = text.split("\r?\n", -1);
        int count = lines.length;
        while (count > 0 && lines[count - 1].isEmpty()) {
            count--;
        }
        titles = count == 0 ? List.of() : split(lines[0], 0);
        for (int i = 1; i < count; i++) {
            rows.add(split(lines[i], titles.size()));
        }
    }

    private static List<String> split(String line, int atLeast) {
        List<String> fields = new ArrayList<>(List.of(line.split(",", -1)));
        while (fields.size() < atLeast) {
            fields.add("");
        }
        return fields;
    }

    @Op("titles")
    PArray titles() {
        return new PArray(titles);
    }

    @Op("size")
    int size() {
        return rows.size();
    }

    @Op("at:")
    PArray at(int index) {
        if (index < 0 || index >= rows.size()) {
            throw new PonderError("index " + index + " out of range for CsvHash of size " + rows.size());
        }
        return new PArray(rows.get(index));
    }

    @Op("do:")
    void each(CallContext ctx, Block body) {
        String[] above = new String[titles.size()];
        for (List<String> row : List.copyOf(rows)) {
            PHash hash = new PHash();
            for (int i = 0; i < titles.size(); i++) {
                String value = row.get(i);
                if (value.isEmpty() && above[i] != null) {
                    value = above[i];
                }
                above[i] = value;
                hash.put(titles.get(i), value);
            }
            ctx.call(body, hash);
        }
    }
}
