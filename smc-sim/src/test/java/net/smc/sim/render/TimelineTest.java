package net.smc.sim.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.io.StringWriter;

import org.junit.jupiter.api.Test;

class TimelineTest {

    @Test
    void csv_hasAHeaderAndOneLinePerRow() throws IOException {
        StringWriter out = new StringWriter();
        new Timeline().record(0, "r1", "ASSIGNED", "surveyor", "iii").record(10_740, "r1", "DISABLED", "hazard:h1", "iv").writeCsv(out);
        assertEquals("time_ms,vehicle,what,detail,step\r\n0,r1,ASSIGNED,surveyor,iii\r\n10740,r1,DISABLED,hazard:h1,iv\r\n",
                out.toString());
    }

    @Test
    void fieldsWithCommasQuotesOrLineBreaks_areQuoted_withQuotesDoubled() {
        assertEquals("plain text", Timeline.quote("plain text"));
        assertEquals("\"at (5.22, 3.94)\"", Timeline.quote("at (5.22, 3.94)"));
        assertEquals("\"avoid \"\"r1\"\"\"", Timeline.quote("avoid \"r1\""));
        assertEquals("\"two\nlines\"", Timeline.quote("two\nlines"));
        assertEquals("\"cr\rhere\"", Timeline.quote("cr\rhere"));
        assertEquals("", Timeline.quote(""));
    }

    @Test
    void negativeTime_isRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Timeline().record(-1, "r1", "X", "", ""));
        assertEquals("timeline row at -1 ms; mission time must be 0 or more", e.getMessage());
    }
}
