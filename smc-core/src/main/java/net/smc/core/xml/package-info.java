/**
 * Positioned XML: reads a small XML document (a mission file, a world file) into a tree of
 * {@link net.smc.core.xml.XmlElement}s that keep the line and column of every start tag and text,
 * so that the readers built on it can name where each error is.
 *
 * <p>Start at {@link net.smc.core.xml.XmlReader}. It reads through the Stax parser of Jackson's XML
 * module (Woodstox), refuses any DOCTYPE (no DTDs, no external entities: these files may come over
 * the network), and bounds the document, every text and every attribute value by the
 * {@link net.smc.core.xml.XmlLimits} it is given. A refused or malformed document is an
 * {@link net.smc.core.xml.XmlRefusal} carrying its line and column.
 *
 * <pre>{@code
 * XmlReader reader = new XmlReader("world file", "missions/worlds/world.xsd", XmlLimits.DEFAULTS);
 * try {
 *     XmlElement root = reader.read(text);
 * } catch (XmlRefusal e) {
 *     reporter.refused(file, e.line(), e.column(), e.getMessage());   // FILE:LINE:COL: what; rule
 * }
 * }</pre>
 */
package net.smc.core.xml;
