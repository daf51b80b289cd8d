package net.smc.core.cell;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

/** The send times of the last 64 heartbeats: what a map of them that forgets its eldest entry would answer. */
class HeartbeatTimesTest {
    @Test
    void answersAsAMapOfTheLast64() {
        HeartbeatTimes times = new HeartbeatTimes();
        Map<Long, Long> map = new LinkedHashMap<>(32, 0.75f, false) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<Long, Long> eldest) {
                return size() > HeartbeatTimes.CAPACITY;
            }
        };
        SplittableRandom random = new SplittableRandom(7);
        long tag = 0;
        for (int i = 0; i < 5_000; i++) {
            // mostly new tags, sometimes an old one again (an id space wrapping round)
            long t = random.nextInt(10) == 0 ? 1 + random.nextLong(Math.max(1, tag)) : ++tag;
            times.put(t, i);
            map.put(t, (long) i);
            for (int k = 0; k < 3; k++) {
                long probe = 1 + random.nextLong(tag + 5);
                assertEquals(map.getOrDefault(probe, HeartbeatTimes.NONE), times.sentAt(probe), "tag " + probe + " after " + i);
            }
        }
    }

    @Test
    void theNewestIsFound_andTheOldestForgotten() {
        HeartbeatTimes times = new HeartbeatTimes();
        for (long t = 1; t <= 65; t++) {
            times.put(t, 1_000 + t);
        }
        assertEquals(1_065, times.sentAt(65));
        assertEquals(1_002, times.sentAt(2));
        assertEquals(HeartbeatTimes.NONE, times.sentAt(1), "the 65th forgets the first");
        times.put(2, 5);
        assertEquals(5, times.sentAt(2), "a tag sent again takes the new time");
        times.put(66, 6);
        assertEquals(HeartbeatTimes.NONE, times.sentAt(2), "and keeps its place: still the oldest, forgotten next");
        assertEquals(1_003, times.sentAt(3));
    }
}
