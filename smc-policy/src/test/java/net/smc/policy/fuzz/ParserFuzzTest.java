package net.smc.policy.fuzz;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;

/**
 * Fuzz targets for the lexer, the parser and the interpreter. In the normal test run Jazzer only
 * replays the seeds in {@code ParserFuzzTestInputs/<method>/} (test resources); fuzz for real with
 * {@code ./gradlew :smc-policy:test -Pfuzz=1 -Ptests='.*ParserFuzzTest'}.
 */
class ParserFuzzTest {

    @FuzzTest
    void lexAndParse(FuzzedDataProvider data) {
        Invariants.lexAndParse(data.consumeRemainingAsString());
    }

    @FuzzTest
    void runInCell(FuzzedDataProvider data) {
        Invariants.runInCell(data.consumeRemainingAsString());
    }
}
