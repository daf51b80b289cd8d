package net.smc.core.xml;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * One element of a document read by {@link XmlReader}, with the place of its start tag and of its
 * text, so that every check can name the line and column of what it rejects. The XML data binding
 * of Jackson maps elements to fields but drops their positions; this small tree keeps them.
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
public record XmlElement(String name, Map<String, String> attributes, String text, int textLine, int textColumn,
                         List<XmlElement> children, int line, int column) {

    public XmlElement {
        attributes = Collections.unmodifiableMap(new LinkedHashMap<>(attributes));
        children = List.copyOf(children);
    }

    /** The tag as messages show it: {@code <name>}. */
    public String tag() {
        return "<" + name + ">";
    }

    /** The value of the attribute called {@code attribute}. */
    public Optional<String> attribute(String attribute) {
        return Optional.ofNullable(attributes.get(attribute));
    }

    /** The children called {@code childName}, in document order. */
    public List<XmlElement> children(String childName) {
        List<XmlElement> found = new ArrayList<>();
        for (XmlElement child : children) {
            if (child.name.equals(childName)) {
                found.add(child);
            }
        }
        return found;
    }

    /** The first child called {@code childName}. */
    public Optional<XmlElement> child(String childName) {
        for (XmlElement child : children) {
            if (child.name.equals(childName)) {
                return Optional.of(child);
            }
        }
        return Optional.empty();
    }
}
