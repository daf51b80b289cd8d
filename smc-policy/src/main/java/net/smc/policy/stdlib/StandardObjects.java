package net.smc.policy.stdlib;

import java.util.LinkedHashMap;
import java.util.Map;

/** The one registry of the standard objects: the name {@code root load:} takes, and the class. */
public final class StandardObjects {
    private StandardObjects() {
    }

    /** Name to class, in the order the language reference lists them. */
    public static Map<String, Class<?>> classes() {
        Map<String, Class<?>> all = new LinkedHashMap<>();
        all.put("Timer", Timer.class);
        all.put("EventForwarder", EventForwarder.class);
        all.put("PonderTalk", PonderTalkEvaluator.class);
        all.put("Semaphore", Semaphore.class);
        all.put("DynamicString", DynamicString.class);
        all.put("CsvHash", CsvHash.class);
        all.put("SampleObject", SampleObject.class);
        return all;
    }

    /** Parses XML text into an XML value ({@code "..." asXML}). */
    public static Object parseXml(String text) {
        return XmlValue.parse(text);
    }
}
