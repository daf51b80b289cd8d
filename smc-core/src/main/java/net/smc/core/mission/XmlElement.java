package net.smc.core.mission;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * One element of a mission file with the place of its start tag, so that every check can name the
 * line and column of what it rejects. The XML data binding of Jackson maps elements to fields but
 * drops their positions; this small tree keeps them.
 *
 * @param name       the element's local name
 * @param attributes its attributes without a namespace, in document order
 * @param text       its own character data, trimmed (empty when it has none)
 * @param textLine   where that text starts (the element's own line when it has none)
 * @param textColumn where that text starts
 * @param children   its child elements, in document order
 * @param line       line of the start tag's {@code <}, from 1
 * @param column     column of the start tag's {@code <}, from 1
 */
record XmlElement(String name, Map<String, String> attributes, String text, int textLine, int textColumn,
                  List<XmlElement> children, int line, int column) {

    XmlElement {
        attributes = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(attributes));
        children = List.copyOf(children);
    }

    /** The tag as messages show it: {@code <name>}. */
    String tag() {
        return "<" + name + ">";
    }

    Optional<String> attribute(String attribute) {
        return Optional.ofNullable(attributes.get(attribute));
    }

    /** The children called {@code childName}, in document order. */
    List<XmlElement> children(String childName) {
        List<XmlElement> found = new ArrayList<>();
        for (XmlElement child : children) {
            if (child.name.equals(childName)) {
                found.add(child);
            }
        }
        return found;
    }

    /** The first child called {@code childName}. */
    Optional<XmlElement> child(String childName) {
        for (XmlElement child : children) {
            if (child.name.equals(childName)) {
                return Optional.of(child);
            }
        }
        return Optional.empty();
    }
}
