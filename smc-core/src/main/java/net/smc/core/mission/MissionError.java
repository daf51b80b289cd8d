package net.smc.core.mission;

import java.nio.file.Path;

/**
 * One problem in a mission file: where it is and what rule it breaks. {@link #toString()} is the
 * diagnostic line {@code FILE:LINE:COL: <element>: message} that {@code smc validate} prints,
 * the same shape as PonderTalk's diagnostics.
 *
 * @param file    the file, as the loader was given it or as the instance's {@code href} resolved
 * @param line    line of the offending element's start tag (or text, or XML syntax error), from 1
 * @param column  column of the same place, from 1
 * @param element the offending element's name, or {@code null} for an XML syntax error
 * @param message what is wrong, then, after a semicolon, the rule it breaks
 */
public record MissionError(Path file, int line, int column, String element, String message) {

    /** {@code FILE:LINE:COL: <element>: message}, or {@code FILE:LINE:COL: message} with no element. */
    @Override
    public String toString() {
        return file + ":" + line + ":" + column + ": " + (element == null ? "" : "<" + element + ">: ") + message;
    }
}
