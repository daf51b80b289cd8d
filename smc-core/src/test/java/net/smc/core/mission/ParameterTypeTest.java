package net.smc.core.mission;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.time.Duration;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ParameterTypeTest {

    @Test
    void eachTypeParsesItsValues() {
        assertEquals(-3, ParameterType.INT.parse("-3"));
        assertEquals(5_000_000_000L, ParameterType.LONG.parse("5000000000"));
        assertEquals(2.5e3, ParameterType.DOUBLE.parse("2.5e3"));
        assertEquals(true, ParameterType.BOOLEAN.parse("true"));
        assertEquals("north gate", ParameterType.STRING.parse("north gate"));
        assertEquals(Duration.ofMillis(500), ParameterType.DURATION.parse("500ms"));
        assertEquals(Duration.ofSeconds(3), ParameterType.DURATION.parse("3s"));
        assertEquals(Duration.ofMinutes(2), ParameterType.DURATION.parse("2min"));
        assertEquals(Duration.ofHours(1), ParameterType.DURATION.parse("1h"));
        assertEquals(Duration.ofSeconds(3), ParameterType.DURATION.parse("PT3S"));
    }

    @ParameterizedTest
    @CsvSource(quoteCharacter = '"', value = {
        "INT, 3000000000, '3000000000' is not an int",
        "INT, 1.5, '1.5' is not an int",
        "LONG, ten, 'ten' is not a long",
        "DOUBLE, NaN, 'NaN' is not a double",
        "DOUBLE, 1d, '1d' is not a double",
        "DOUBLE, 0x1p3, '0x1p3' is not a double",
        "BOOLEAN, yes, 'yes' is not a boolean",
        "DURATION, 3000, \"'3000' is not a duration (write 500ms, 3s, 2min, 1h or ISO-8601 such as PT3S)\"",
        "DURATION, PT-3S, 'PT-3S' is not a duration (a duration is not negative)"})
    void parse_rejectsTextThatIsNotAValue_namingTheTextAndType(ParameterType type, String text, String message) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> type.parse(text));

        assertEquals(message, e.getMessage());
    }

    @Test
    void fromXmlName_knowsTheSixNames() {
        assertEquals(Optional.of(ParameterType.DURATION), ParameterType.fromXmlName("duration"));
        assertEquals(Optional.empty(), ParameterType.fromXmlName("integer"));
        assertEquals("int, long, double, boolean, string, duration", ParameterType.names());
    }

    @Test
    void parameter_accessorOfTheWrongType_namesBothTypes() {
        Parameter timeout = new Parameter("comTimeout", ParameterType.INT, 500);

        IllegalStateException e = assertThrows(IllegalStateException.class, timeout::asDuration);

        assertEquals("parameter 'comTimeout' is int, not duration", e.getMessage());
        assertEquals(500L, timeout.asLong());
        assertEquals(500.0, timeout.asDouble());
    }

    @Test
    void parameter_valueMustMatchItsType() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Parameter("comTimeout", ParameterType.INT, "500"));

        assertEquals("parameter 'comTimeout' of type int has a String value; it must be an Integer", e.getMessage());
    }
}
