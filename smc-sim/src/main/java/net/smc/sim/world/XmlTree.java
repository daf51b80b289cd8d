package net.smc.sim.world;

import com.fasterxml.jackson.dataformat.xml.XmlFactory;
import java.io.StringReader;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.xml.stream.Location;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;

/**
 * A world file as a tree of elements that remember where their start tags are, read through the
 * Stax parser of Jackson's {@link XmlFactory} (Woodstox). Data binding would forget positions, and
 * every error must name its line and column. DTDs and external entities are refused.
 */
final class XmlTree {

    /** One element: its name, attributes, trimmed own text, children, and start-tag position. */
    record Element(String name, Map<String, String> attributes, String text, List<Element> children,
                   int line, int column) {

        String tag() {
            return "<" + name + ">";
        }
    }

    /** Thrown for text that is not well-formed XML, with the parser's position. */
    static final class SyntaxError extends Exception {
        final int line;
        final int column;

        SyntaxError(int line, int column, String message) {
            super(message, null, false, false);
            this.line = line;
            this.column = column;
        }
    }

    private XmlTree() {
    }

    static Element parse(String text) throws SyntaxError {
        XMLInputFactory factory = new XmlFactory().getXMLInputFactory();
        factory.setProperty(XMLInputFactory.SUPPORT_DTD, Boolean.FALSE);
        factory.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, Boolean.FALSE);
        factory.setProperty(XMLInputFactory.IS_COALESCING, Boolean.TRUE);
        XMLStreamReader reader = null;
        try {
            reader = factory.createXMLStreamReader(new StringReader(text));
            return document(reader);
        } catch (XMLStreamException e) {
            Location at = e.getLocation();
            String message = String.valueOf(e.getMessage());
            int cut = message.indexOf("\n at [");
            message = (cut < 0 ? message : message.substring(0, cut)).strip();
            throw new SyntaxError(at == null ? 1 : Math.max(1, at.getLineNumber()),
                    at == null ? 1 : Math.max(1, at.getColumnNumber()), message);
        } finally {
            if (reader != null) {
                try {
                    reader.close();
                } catch (XMLStreamException ignored) {
                    // reading a string: nothing to release
                }
            }
        }
    }

    private static Element document(XMLStreamReader reader) throws XMLStreamException {
        Deque<Open> open = new ArrayDeque<>();
        Element root = null;
        while (reader.hasNext()) {
            switch (reader.next()) {
                case XMLStreamConstants.START_ELEMENT -> open.push(new Open(reader));
                case XMLStreamConstants.CHARACTERS, XMLStreamConstants.CDATA, XMLStreamConstants.SPACE -> {
                    if (!open.isEmpty()) {
                        open.peek().text.append(reader.getText());
                    }
                }
                case XMLStreamConstants.END_ELEMENT -> {
                    Open done = open.pop();
                    Element element = new Element(done.name, done.attributes, done.text.toString().strip(),
                            List.copyOf(done.children), done.line, done.column);
                    if (open.isEmpty()) {
                        root = element;
                    } else {
                        open.peek().children.add(element);
                    }
                }
                default -> {
                    // comments, processing instructions, the document's end
                }
            }
        }
        return root;
    }

    private static final class Open {
        final String name;
        final Map<String, String> attributes = new LinkedHashMap<>();
        final StringBuilder text = new StringBuilder();
        final List<Element> children = new ArrayList<>();
        final int line;
        final int column;

        Open(XMLStreamReader reader) {
            name = reader.getLocalName();
            Location at = reader.getLocation();
            line = at.getLineNumber();
            column = at.getColumnNumber();
            for (int i = 0; i < reader.getAttributeCount(); i++) {
                String namespace = reader.getAttributeNamespace(i);
                if (namespace == null || namespace.isEmpty()) {
                    attributes.put(reader.getAttributeLocalName(i), reader.getAttributeValue(i));
                }
            }
        }
    }
}
