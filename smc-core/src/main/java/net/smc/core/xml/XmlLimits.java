package net.smc.core.xml;

/**
 * How much an {@link XmlReader} accepts; anything larger is refused before or while it is read.
 *
 * @param maxFileBytes      the largest document, in bytes for a file ({@link XmlReader#readFile}) and
 *                          in characters for a text ({@link XmlReader#read}); at least 1
 * @param maxTextChars      the most characters of text one element may have; at least 1
 * @param maxAttributeChars the most characters one attribute value may have; at least 1
 */
public record XmlLimits(long maxFileBytes, int maxTextChars, int maxAttributeChars) {
    /** 1 MiB documents, 4096 characters of text per element and per attribute value. */
    public static final XmlLimits DEFAULTS = new XmlLimits(1024 * 1024, 4096, 4096);

    public XmlLimits {
        if (maxFileBytes < 1) {
            throw new IllegalArgumentException("maxFileBytes is " + maxFileBytes + "; it must be 1 or more");
        }
        if (maxTextChars < 1) {
            throw new IllegalArgumentException("maxTextChars is " + maxTextChars + "; it must be 1 or more");
        }
        if (maxAttributeChars < 1) {
            throw new IllegalArgumentException("maxAttributeChars is " + maxAttributeChars + "; it must be 1 or more");
        }
    }
}
