package net.smc.core.mission;

import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import net.smc.core.xml.XmlElement;

/**
 * Collects the errors of one mission file, plus the shape checks every reader shares (which
 * attributes an element takes, whether it holds text or elements). Readers report and go on, so
 * that a file's every error is listed; nothing here throws.
 */
final class Reporter {
    private final Path file;
    private final List<MissionError> sink;

    Reporter(Path file, List<MissionError> sink) {
        this.file = file;
        this.sink = sink;
    }

    /** An error at an element's start tag. */
    void error(XmlElement at, String message) {
        sink.add(new MissionError(file, at.line(), at.column(), at.name(), message));
    }

    /** An error at an element's text. */
    void textError(XmlElement at, String message) {
        sink.add(new MissionError(file, at.textLine(), at.textColumn(), at.name(), message));
    }

    /** An error with no element (XML syntax). */
    void syntaxError(int line, int column, String message) {
        sink.add(new MissionError(file, Math.max(line, 1), Math.max(column, 1), null, message));
    }

    /** Reports each attribute of {@code el} that is not in {@code allowed}. */
    void attributes(XmlElement el, Set<String> allowed) {
        for (String attribute : el.attributes().keySet()) {
            if (!allowed.contains(attribute)) {
                error(el, "unexpected attribute '" + attribute + "'; " + el.tag() + " takes "
                        + (allowed.isEmpty() ? "no attributes" : "only " + String.join(", ", sorted(allowed))));
            }
        }
    }

    /** Reports attributes and text on an element that holds elements only and takes no attributes. */
    void container(XmlElement el) {
        attributes(el, Set.of());
        noText(el);
    }

    /** Reports text inside an element that holds elements only. */
    void noText(XmlElement el) {
        if (!el.text().isEmpty()) {
            textError(el, "unexpected text '" + abbreviate(el.text()) + "'; " + el.tag()
                    + " holds elements only (write comments as <!-- ... -->)");
        }
    }

    /**
     * The text of an element that holds text only; its child elements and attributes are reported.
     *
     * @param what what the text is, for the message when it is empty ({@code "a role name"}), or
     *             {@code null} when empty text is allowed
     */
    String leaf(XmlElement el, String what) {
        attributes(el, Set.of());
        for (XmlElement child : el.children()) {
            error(child, "unexpected element; " + el.tag() + " holds text only");
        }
        if (what != null && el.text().isEmpty()) {
            error(el, "empty; " + el.tag() + " must hold " + what);
        }
        return el.text();
    }

    /** Reports an element found where it does not belong, listing what does. */
    void unexpected(XmlElement el, XmlElement parent, String expected) {
        error(el, "unexpected element in " + parent.tag() + "; expected " + expected);
    }

    /** Reports a second (third ...) occurrence of an element that may appear once. */
    void once(List<XmlElement> occurrences, XmlElement parent) {
        for (int i = 1; i < occurrences.size(); i++) {
            error(occurrences.get(i), "appears more than once in " + parent.tag() + "; it may appear at most once");
        }
    }

    static String abbreviate(String text) {
        String oneLine = text.replaceAll("\\s+", " ");
        return oneLine.length() <= 40 ? oneLine : oneLine.substring(0, 37) + "...";
    }

    private static List<String> sorted(Set<String> names) {
        return names.stream().sorted().toList();
    }
}
