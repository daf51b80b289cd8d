package net.smc.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import java.util.Set;
import net.smc.scenario.DependencyRules.Source;
import org.junit.jupiter.api.Test;

/** Shows each architecture rule failing on a small synthetic project, and passing when kept. */
class DependencyRulesTest {
    private static final DependencyRules RULES = new DependencyRules(List.of("low", "high"),
            Map.of("x.low.inside", "low"));

    private static Source file(String module, String pkg, String type, String body) {
        String path = module + "/" + pkg.replace('.', '/') + "/" + type + ".java";
        return new Source(module, path, "package " + pkg + ";\n\n" + body + "\npublic final class " + type + " {\n}\n");
    }

    @Test
    void sourcesThatKeepEveryRule_haveNoViolations() {
        List<Source> sources = List.of(
                file("low", "x.low.api", "Api", ""),
                file("low", "x.low.inside", "Engine", "import x.low.api.Api;"),
                file("high", "x.high", "User", "import x.low.api.Api;"));

        assertEquals(List.of(), RULES.violations(sources));
    }

    @Test
    void packageCycle_isAViolation() {
        List<Source> sources = List.of(
                file("low", "x.low.a", "A", "import x.low.b.B;"),
                file("low", "x.low.b", "B", "import x.low.a.A;"));

        assertEquals(List.of("package cycle: x.low.a -> x.low.b (low/x/low/a/A.java), x.low.b -> x.low.a (low/x/low/b/B.java)"),
                RULES.violations(sources));
    }

    @Test
    void longerPackageCycle_isFoundThroughFullyQualifiedNames() {
        List<Source> sources = List.of(
                file("low", "x.low.a", "A", "class Uses { Object o = new x.low.b.B(); }"),
                file("low", "x.low.b", "B", "import static x.low.c.C.helper;"),
                file("low", "x.low.c", "C", "import x.low.a.*;"));

        assertEquals(List.of("package cycle: x.low.a -> x.low.b (low/x/low/a/A.java), x.low.b -> x.low.c (low/x/low/b/B.java),"
                + " x.low.c -> x.low.a (low/x/low/c/C.java)"), RULES.violations(sources));
    }

    @Test
    void importAgainstTheModuleDirection_isAViolation() {
        List<Source> sources = List.of(
                file("low", "x.low.api", "Api", "import x.high.User;"),
                file("high", "x.high", "User", ""));

        assertEquals(List.of("module direction: low/x/low/api/Api.java (low) uses x.high (high); low may use only []"),
                RULES.violations(sources));
    }

    @Test
    void importIntoAnotherModulesInside_isAViolation() {
        List<Source> sources = List.of(
                file("low", "x.low.inside", "Engine", ""),
                file("high", "x.high", "User", "import x.low.inside.Engine;"));

        assertEquals(List.of("inside package: high/x/high/User.java (high) uses x.low.inside, the inside of low;"
                + " use its public packages"), RULES.violations(sources));
    }

    @Test
    void twoMainTypesWithOneSimpleName_areAViolation() {
        List<Source> sources = List.of(
                file("low", "x.low.a", "Codec", ""),
                file("high", "x.high", "Codec", ""));

        assertEquals(List.of("simple name: 2 main types are called Codec: [x.low.a.Codec, x.high.Codec]"),
                RULES.violations(sources));
    }

    @Test
    void commentsAndStrings_makeNoDependency() {
        String body = """
                /** See {@link x.low.b.B}; import x.low.b.B; */
                // import x.low.b.B;
                class Quiet { String s = "x.low.b.B"; String t = \"""
                        x.low.b.B
                        \"""; char c = '"'; }
                """;
        Source a = file("low", "x.low.a", "A", body);

        assertEquals(Set.of(), DependencyRules.referencedPackages(a.text()));
        assertEquals(List.of(), RULES.violations(List.of(a, file("low", "x.low.b", "B", "import x.low.a.A;"))));
    }

    @Test
    void importsOfClassesMembersAndWildcards_nameTheirPackage() {
        String text = "package p;\nimport x.low.a.A;\nimport x.low.b.B.Inner;\nimport static x.low.c.C.MAX;\nimport x.low.d.*;\n";

        assertEquals(Set.of("x.low.a", "x.low.b", "x.low.c", "x.low.d"), DependencyRules.referencedPackages(text));
    }
}
