package net.smc.core.xml;

import com.fasterxml.jackson.dataformat.xml.XmlFactory;
import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import javax.xml.stream.Location;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import net.smc.policy.lang.SourceFiles;

/**
 * Reads a document into a tree of {@link XmlElement}s that keep their positions, through the Stax
 * parser of Jackson's {@link XmlFactory} (Woodstox). Jackson's data binding would map the elements
 * straight to records, but it forgets where each element was, and every error must name its line
 * and column. DTDs and external entities are refused, and sizes are bounded by {@link XmlLimits}:
 * the documents read (mission files, world files) may come from elsewhere.
 *
 * <p>A reader keeps no state between reads (its Stax factory is configured once and only creates
 * stream readers), so threads may share one.
 */
public final class XmlReader {
    private final String document;
    private final String format;
    private final XmlLimits limits;
    private final XMLInputFactory factory;

    /**
     * A reader of one kind of document.
     *
     * @param document what the document is, as messages name it ("mission file")
     * @param format   where its format is described, as messages name it ("missions/*.xsd")
     * @param limits   what it accepts
     */
    public XmlReader(String document, String format, XmlLimits limits) {
        this.document = Objects.requireNonNull(document, "document");
        this.format = Objects.requireNonNull(format, "format");
        this.limits = Objects.requireNonNull(limits, "limits");
        factory = new XmlFactory().getXMLInputFactory();
        factory.setProperty(XMLInputFactory.SUPPORT_DTD, Boolean.FALSE);
        factory.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, Boolean.FALSE);
        factory.setProperty(XMLInputFactory.IS_COALESCING, Boolean.TRUE);
    }

    public XmlLimits limits() {
        return limits;
    }

    /**
     * The text of {@code file}: UTF-8 (a leading byte-order mark skipped), or UTF-16 with a
     * byte-order mark; refused unread when it is larger than {@link XmlLimits#maxFileBytes()}, and
     * refused naming the first byte that is not part of a character of its encoding (its offset and
     * line), whatever encoding the XML declaration names.
     */
    public String readFile(Path file) throws IOException {
        long size = Files.size(file);
        if (size > limits.maxFileBytes()) {
            throw new IOException("file of " + size + " bytes is larger than the limit of " + limits.maxFileBytes()
                    + " bytes for a " + document);
        }
        return SourceFiles.decode(Files.readAllBytes(file));
    }

    /**
     * The root element of {@code text} ({@code null} for a document without one).
     *
     * @throws XmlRefusal when the text is not well-formed XML (the parser stops at the first such
     *                    error, so it is the only one), has a DOCTYPE, or is beyond the limits
     */
    public XmlElement read(String text) throws XmlRefusal {
        if (text.length() > limits.maxFileBytes()) {
            throw new XmlRefusal(1, 1, "the text has " + text.length() + " characters; a " + document
                    + " may have at most " + limits.maxFileBytes());
        }
        XMLStreamReader reader = null;
        try {
            reader = factory.createXMLStreamReader(new StringReader(text));
            return readDocument(reader);
        } catch (Refused e) {
            throw new XmlRefusal(e.line, e.column, e.getMessage());
        } catch (XMLStreamException e) {
            throw notWellFormed(e);
        } catch (RuntimeException e) {
            // Woodstox reports some errors in text (a stray '&', an unknown entity) only when the
            // text is asked for, wrapped unchecked
            if (e.getCause() instanceof XMLStreamException x) {
                throw notWellFormed(x);
            }
            throw e;
        } finally {
            close(reader);
        }
    }

    private XmlElement readDocument(XMLStreamReader reader) throws XMLStreamException {
        Deque<Builder> open = new ArrayDeque<>();
        XmlElement root = null;
        while (reader.hasNext()) {
            int event = reader.next();
            switch (event) {
                case XMLStreamConstants.START_ELEMENT -> open.push(new Builder(reader, limits));
                case XMLStreamConstants.DTD -> {
                    Location at = reader.getLocation();
                    throw new Refused(at.getLineNumber(), at.getColumnNumber(), "a DOCTYPE declaration is not "
                            + "allowed; a " + document + " has no DTD (its format is " + format
                            + "), so remove <!DOCTYPE ...>");
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

    private XmlRefusal notWellFormed(XMLStreamException e) {
        Location at = e.getLocation();
        return new XmlRefusal(at == null ? 1 : at.getLineNumber(), at == null ? 1 : at.getColumnNumber(),
                "not well-formed XML: " + cause(e) + "; a " + document + " must be well-formed XML");
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

    /** A rule broken while reading: leaves the Stax loop at once, at a position. */
    private static final class Refused extends RuntimeException {
        private static final long serialVersionUID = 1L;
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
        final int maxTextChars;
        final StringBuilder text = new StringBuilder();
        int textLine;
        int textColumn;
        final List<XmlElement> children = new ArrayList<>();

        Builder(XMLStreamReader reader, XmlLimits limits) {
            name = reader.getLocalName();
            Location at = reader.getLocation();
            line = at.getLineNumber();
            column = at.getColumnNumber();
            maxTextChars = limits.maxTextChars();
            for (int i = 0; i < reader.getAttributeCount(); i++) {
                String namespace = reader.getAttributeNamespace(i);
                if (namespace == null || namespace.isEmpty()) {
                    String value = reader.getAttributeValue(i);
                    if (value.length() > limits.maxAttributeChars()) {
                        throw new Refused(line, column, "<" + name + ">: attribute '" + reader.getAttributeLocalName(i)
                                + "' has " + value.length() + " characters; an attribute value may have at most "
                                + limits.maxAttributeChars());
                    }
                    attributes.put(reader.getAttributeLocalName(i), value);
                }
            }
        }

        void text(XMLStreamReader reader) {
            String chunk = reader.getText();
            if (text.isEmpty() && chunk.isBlank()) {
                return;   // the layout between elements: not text, and not counted against the limit
            }
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
            if ((long) text.length() + chunk.length() > maxTextChars) {
                throw new Refused(line, column, "<" + name + ">: its text is longer than " + maxTextChars
                        + " characters; the text of an element may have at most " + maxTextChars);
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
