package net.smc.sim.arena;

import java.nio.file.Path;

/**
 * One problem in a world file: where it is and the rule it breaks. {@link #toString()} is the
 * diagnostic line {@code FILE:LINE:COL: <element>: message}, as for mission files.
 *
 * @param file    the file as the reader was given it
 * @param line    line of the offending start tag (or XML syntax error), from 1
 * @param column  column of the same place, from 1
 * @param element the offending element's name, or {@code null} for an XML syntax error
 * @param message what is wrong, then, after a semicolon, the rule it breaks
 */
public record ArenaError(Path file, int line, int column, String element, String message) {

    @Override
    public String toString() {
        return file + ":" + line + ":" + column + ": " + (element == null ? "" : "<" + element + ">: ") + message;
    }
}
