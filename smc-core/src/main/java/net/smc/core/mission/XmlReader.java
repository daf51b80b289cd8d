package net.smc.core.mission;

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
 * Reads a mission file into a tree of {@link XmlElement}s that keep their positions, through the
 * Stax parser of Jackson's {@link XmlFactory} (Woodstox). Jackson's data binding would map the
 * elements straight to records, but it forgets where each element was, and every error must name
 * its line and column. DTDs and external entities are refused: mission files come from a command
 * base over the network.
 */
final class XmlReader {
    /** The most characters of text an element, or an attribute value, of a mission file may have. */
    static final int MAX_TEXT_CHARS = 4096;

    private final XMLInputFactory factory;

    XmlReader() {
        factory = new XmlFactory().getXMLInputFactory();
        factory.setProperty(XMLInputFactory.SUPPORT_DTD, Boolean.FALSE);
        factory.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, Boolean.FALSE);
        factory.setProperty(XMLInputFactory.IS_COALESCING, Boolean.TRUE);
    }

    /**
     * The root element of {@code text}, or {@code null} after reporting why the text is not
     * well-formed XML (the parser stops at the first such error, so this is the only one).
     */
    XmlElement read(String text, Reporter reporter) {
        XMLStreamReader reader = null;
        try {
            reader = factory.createXMLStreamReader(new StringReader(text));
            return readDocument(reader);
        } catch (Refused e) {
            reporter.syntaxError(e.line, e.column, e.getMessage());
            return null;
        } catch (XMLStreamException e) {
            Location at = e.getLocation();
            reporter.syntaxError(at == null ? 1 : at.getLineNumber(), at == null ? 1 : at.getColumnNumber(),
                    "not well-formed XML: " + cause(e) + "; a mission file must be well-formed XML");
            return null;
        } finally {
            close(reader);
        }
    }

    private static XmlElement readDocument(XMLStreamReader reader) throws XMLStreamException {
        Deque<Builder> open = new ArrayDeque<>();
        XmlElement root = null;
        while (reader.hasNext()) {
            int event = reader.next();
            switch (event) {
                case XMLStreamConstants.START_ELEMENT -> open.push(new Builder(reader));
                case XMLStreamConstants.DTD -> {
                    Location at = reader.getLocation();
                    throw new Refused(at.getLineNumber(), at.getColumnNumber(), "a DOCTYPE declaration is not "
                            + "allowed; a mission file has no DTD (its format is missions/*.xsd), so remove <!DOCTYPE ...>");
                }
                case XMLStreamConstants.CHARACTERS, XMLStreamConstants.CDATA, XMLStreamConstants.SPACE -> {
                    if (!open.isEmpty()) {
                        open.peek().text(reader);
                    }
                }
                case XMLStreamConstants.END_ELEMENT -> {
                    XmlElement done = open.pop().build();
                    if (open.isEmpty()) {
                        root = done;
                    } else {
                        open.peek().children.add(done);
                    }
                }
                default -> {
                    // comments, processing instructions, the document's end
                }
            }
        }
        return root;
    }

    /** Woodstox appends " at [row,col ...]" to its messages; the position is reported apart. */
    private static String cause(XMLStreamException e) {
        String message = String.valueOf(e.getMessage());
        int at = message.indexOf("\n at [");
        String cause = (at < 0 ? message : message.substring(0, at)).strip();
        return cause.endsWith(".") ? cause.substring(0, cause.length() - 1) : cause;
    }

    private static void close(XMLStreamReader reader) {
        if (reader != null) {
            try {
                reader.close();
            } catch (XMLStreamException ignored) {
                // reading a string: nothing to release
            }
        }
    }

    /** A rule of mission files broken while reading: ends the read, at a position. */
    private static final class Refused extends RuntimeException {
        final int line;
        final int column;

        Refused(int line, int column, String message) {
            super(message, null, false, false);
            this.line = line;
            this.column = column;
        }
    }

    /** An element whose end tag has not been read yet. */
    private static final class Builder {
        final String name;
        final Map<String, String> attributes = new LinkedHashMap<>();
        final int line;
        final int column;
        final StringBuilder text = new StringBuilder();
        int textLine;
        int textColumn;
        final List<XmlElement> children = new ArrayList<>();

        Builder(XMLStreamReader reader) {
            name = reader.getLocalName();
            Location at = reader.getLocation();
            line = at.getLineNumber();
            column = at.getColumnNumber();
            for (int i = 0; i < reader.getAttributeCount(); i++) {
                String namespace = reader.getAttributeNamespace(i);
                if (namespace == null || namespace.isEmpty()) {
                    String value = reader.getAttributeValue(i);
                    if (value.length() > MAX_TEXT_CHARS) {
                        throw new Refused(line, column, "<" + name + ">: attribute '" + reader.getAttributeLocalName(i)
                                + "' has " + value.length() + " characters; an attribute value may have at most "
                                + MAX_TEXT_CHARS);
                    }
                    attributes.put(reader.getAttributeLocalName(i), value);
                }
            }
        }

        void text(XMLStreamReader reader) {
            String chunk = reader.getText();
            if (textLine == 0 && !chunk.isBlank()) {
                Location at = reader.getLocation();
                int line = at.getLineNumber();
                int column = at.getColumnNumber();
                // Point at the first non-blank character, not at the whitespace before it.
                for (int i = 0; i < chunk.length() && Character.isWhitespace(chunk.charAt(i)); i++) {
                    if (chunk.charAt(i) == '\n') {
                        line++;
                        column = 1;
                    } else {
                        column++;
                    }
                }
                textLine = line;
                textColumn = column;
            }
            if ((long) text.length() + chunk.length() > MAX_TEXT_CHARS) {
                throw new Refused(line, column, "<" + name + ">: its text is longer than " + MAX_TEXT_CHARS
                        + " characters; the text of an element may have at most " + MAX_TEXT_CHARS);
            }
            text.append(chunk);
        }

        XmlElement build() {
            String trimmed = text.toString().strip();
            return new XmlElement(name, attributes, trimmed, trimmed.isEmpty() ? line : textLine,
                    trimmed.isEmpty() ? column : textColumn, children, line, column);
        }
    }
}
