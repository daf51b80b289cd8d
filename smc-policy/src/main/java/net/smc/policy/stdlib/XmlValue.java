package net.smc.policy.stdlib;

import java.io.StringReader;
import java.io.StringWriter;
import java.math.BigDecimal;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.transform.OutputKeys;
import javax.xml.transform.Transformer;
import javax.xml.transform.TransformerFactory;
import javax.xml.transform.dom.DOMSource;
import javax.xml.transform.stream.StreamResult;
import javax.xml.xpath.XPathConstants;
import javax.xml.xpath.XPathExpressionException;
import javax.xml.xpath.XPathFactory;
import net.smc.policy.api.Managed;
import net.smc.policy.runtime.ManagedObject;
import net.smc.policy.api.Op;
import net.smc.policy.runtime.PArray;
import net.smc.policy.api.PonderError;
import org.w3c.dom.Document;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;
import org.xml.sax.InputSource;
import org.xml.sax.SAXException;

/**
 * An XML document or node ({@code "<a>..</a>" asXML}), with Ponder2's XPath queries:
 * {@code xpathString:}, {@code xpathNumber:}, {@code xpathBoolean:}, {@code xpathNode:} (the first
 * matching node, or nil) and {@code xpathNodeSet:} (an array of nodes); {@code asString}. Prints as
 * its serialised text (a document with its {@code <?xml ...?>} declaration). Parsing uses the JDK's
 * parser with DTDs and external entities refused, so no text can make it read a file or the network.
 */
@Managed("XML")
final class XmlValue extends ManagedObject {
    private final Node node;

    private XmlValue(Node node) {
        this.node = node;
    }

    static XmlValue parse(String text) {
        try {
            DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
            f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            f.setFeature("http://xml.org/sax/features/external-general-entities", false);
            f.setFeature("http://xml.org/sax/features/external-parameter-entities", false);
            f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            f.setAttribute(XMLConstants.ACCESS_EXTERNAL_DTD, "");
            f.setAttribute(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
            f.setXIncludeAware(false);
            f.setExpandEntityReferences(false);
            DocumentBuilder builder = f.newDocumentBuilder();
            builder.setErrorHandler(null);
            Document doc = builder.parse(new InputSource(new StringReader(text)));
            doc.setXmlStandalone(true);
            return new XmlValue(doc);
        } catch (SAXException e) {
            throw new PonderError(e.getMessage() != null && e.getMessage().contains("DOCTYPE")
                    ? "not XML: a DOCTYPE is not allowed" : "not XML: " + e.getMessage());
        } catch (Exception e) {
            throw new PonderError("cannot parse XML: " + e.getMessage());
        }
    }

    private Object query(String expression, javax.xml.namespace.QName kind) {
        try {
            return XPathFactory.newInstance().newXPath().evaluate(expression, node, kind);
        } catch (XPathExpressionException e) {
            throw new PonderError("bad XPath expression '" + expression + "'");
        }
    }

    @Op("xpathString:")
    String xpathString(String expression) {
        return (String) query(expression, XPathConstants.STRING);
    }

    @Op("xpathNumber:")
    BigDecimal xpathNumber(String expression) {
        Double d = (Double) query(expression, XPathConstants.NUMBER);
        if (d.isNaN() || d.isInfinite()) {
            throw new PonderError("XPath '" + expression + "' is not a number");
        }
        return d == Math.rint(d) && Math.abs(d) < 1e15 ? BigDecimal.valueOf(d.longValue()) : new BigDecimal(Double.toString(d));
    }

    @Op("xpathBoolean:")
    boolean xpathBoolean(String expression) {
        return (Boolean) query(expression, XPathConstants.BOOLEAN);
    }

    @Op("xpathNode:")
    Object xpathNode(String expression) {
        Node found = (Node) query(expression, XPathConstants.NODE);
        return found == null ? net.smc.policy.api.Nil.NIL : new XmlValue(found);
    }

    @Op("xpathNodeSet:")
    PArray xpathNodeSet(String expression) {
        NodeList found = (NodeList) query(expression, XPathConstants.NODESET);
        PArray result = new PArray();
        for (int i = 0; i < found.getLength(); i++) {
            result.add(new XmlValue(found.item(i)));
        }
        return result;
    }

    @Op("asString")
    String asString() {
        try {
            Transformer t = TransformerFactory.newInstance().newTransformer();
            t.setOutputProperty(OutputKeys.OMIT_XML_DECLARATION, node instanceof Document ? "no" : "yes");
            t.setOutputProperty(OutputKeys.ENCODING, "UTF-8");
            StringWriter out = new StringWriter();
            t.transform(new DOMSource(node), new StreamResult(out));
            return out.toString();
        } catch (Exception e) {
            throw new PonderError("cannot write XML: " + e.getMessage());
        }
    }

    @Override
    public String toString() {
        return asString();
    }
}
