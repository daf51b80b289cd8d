package net.smc.policy.runtime;

import net.smc.policy.api.Nil;
import net.smc.policy.api.Managed;
import net.smc.policy.api.Op;
import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import net.smc.policy.PolicyEngine;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.RunResult;
import net.smc.policy.lang.SourcePos;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Managed objects driven from PonderTalk (smc-policy/PONDERTALK.md section 6): dispatch tables built from
 * {@link Op} annotations, argument conversion by declared type, results, and the errors of each.
 */
class DispatchTest {

    /** A managed class with operations of every arity and parameter type. */
    public static class Counter {
        private long count;
        private String owner = "";

        @Op("create")
        public Counter() {
        }

        @Op("create:")
        public Counter(int start) {
            count = start;
        }

        @Op("startingAt:step:")
        static Counter startingAt(long start, long step) {
            Counter c = new Counter();
            c.count = start + step;
            return c;
        }

        @Op("ownedBySender")
        static Counter ownedBySender(CallContext ctx) {
            Counter c = new Counter();
            c.owner = Values.className(ctx.subject());
            return c;
        }

        @Op("failing")
        static Counter failing() {
            throw new IllegalStateException("no counters today");
        }

        @Op("count")
        public long count() {
            return count;
        }

        @Op("owner")
        public String owner() {
            return owner;
        }

        @Op("add:")
        public void add(int n) {
            count += n;
        }

        @Op("addLong:")
        public void addLong(long n) {
            count += n;
        }

        @Op("addNumber:")
        public void addNumber(BigDecimal n) {
            count += n.longValue();
        }

        @Op("+")
        public long plus(int n) {
            return count + n;
        }

        @Op("scale:")
        public double scale(double factor) {
            return count * factor;
        }

        @Op("notANumber")
        public double notANumber() {
            return Double.NaN;
        }

        @Op("label:")
        public String label(String name) {
            return name + "=" + count;
        }

        @Op("negate:")
        public boolean negate(boolean b) {
            return !b;
        }

        @Op("apply:")
        public Object apply(CallContext ctx, Block block) {
            return ctx.call(block, BigDecimal.valueOf(count));
        }

        @Op("sum:")
        public BigDecimal sum(PArray numbers) {
            BigDecimal total = BigDecimal.ZERO;
            for (Object o : numbers.items()) {
                total = total.add((BigDecimal) o);
            }
            return total;
        }

        @Op("keysOf:")
        public PArray keysOf(PHash hash) {
            PArray keys = new PArray();
            hash.entries().forEach(e -> keys.add(e.getKey()));
            return keys;
        }

        @Op("echo:")
        public Object echo(Object anything) {
            return anything;
        }

        @Op("nothing")
        public Object nothing() {
            return null;
        }

        @Op("join:with:and:")
        public String join3(String a, int b, boolean c) {
            return a + b + c;
        }

        @Op("a:b:c:d:")
        public String join4(String a, long b, double c, BigDecimal d) {
            return a + "," + b + "," + c + "," + d;
        }

        @Op("a:b:c:d:e:")
        public String join5(int a, int b, int c, int d, String e) {
            return (a + b + c + d) + e;
        }

        @Op("boom")
        public void boom() {
            throw new IllegalStateException("kaput");
        }

        @Op("me")
        public Object me(CallContext ctx) {
            return ctx.receiver();
        }

        @Op("sender")
        public Object sender(CallContext ctx) {
            return ctx.subject();
        }

        @Op("list")
        public List<Integer> list() {
            return List.of(1, 2, 3);
        }

        @Op("map")
        public Map<String, Object> map() {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("a", 1);
            m.put("b", "two");
            return m;
        }

        @Op("friend")
        public Friend friend() {
            return new Friend();
        }

        @Op("greet:")
        public String greet(Friend f) {
            return "hello " + f.name();
        }
    }

    /** A plain annotated Java class that is returned by an operation, never registered. */
    public static class Friend {
        @Op("name")
        public String name() {
            return "fred";
        }
    }

    /** A class shown under another name. */
    @Managed("Gadget")
    public static class Widget {
        @Op("create")
        public Widget() {
        }
    }

    public static class Bad {
        @Op("at:put:")
        public void put(Object onlyOne) {
        }
    }

    public static class BadUnary {
        @Op("size")
        public int size(int unexpected) {
            return unexpected;
        }
    }

    public static class BadBinary {
        @Op("+")
        public int plus(int a, int b) {
            return a + b;
        }
    }

    public static class BadConstructor {
        @Op("create:")
        public BadConstructor() {
        }
    }

    public static class Twice {
        @Op("x")
        public int one() {
            return 1;
        }

        @Op("x")
        public int two() {
            return 2;
        }
    }

    private final List<String> output = new ArrayList<>();
    private final List<Diagnostic> errors = new ArrayList<>();
    private PolicyEngine cell;

    @BeforeEach
    void newCell() {
        cell = PolicyEngine.builder()
                .output(output::add)
                .errors(errors::add)
                .register("Counter", Counter.class)
                .register("Widget", Widget.class)
                .build();
    }

    /** Runs a unit that must succeed; answers the printed form of its value. */
    private String eval(String text) {
        RunResult result = cell.run("t.p2", text);
        assertEquals(List.of(), errors, "errors of " + text);
        assertEquals(RunResult.Status.OK, result.status(), text);
        return PolicyEngine.print(result.value());
    }

    /** Runs a unit that must fail with one runtime error; answers its message. */
    private String error(String text) {
        RunResult result = cell.run("t.p2", text);
        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status(), text);
        assertEquals(1, errors.size(), "errors of " + text + ": " + errors);
        return errors.get(0).message();
    }

    private static final String NEW = "c := (root load: \"Counter\") create. ";

    // ---- factories ----

    @Test
    void load_answersTheFactoryOfARegisteredClass() {
        assertEquals("Factory", eval("(root load: \"Counter\") class"));
    }

    @Test
    void load_ofAnUnregisteredName_isAnError() {
        String message = error("root load: \"Nope\"");
        assertTrue(message.startsWith("Load Managed Object - Adaptor for 'Nope' not found; loadable: "), message);
        assertTrue(message.contains(" Counter,") && message.contains(" Timer"), message);
    }

    @Test
    void constructor_withoutArguments() {
        assertEquals("0", eval(NEW + "c count"));
    }

    @Test
    void constructor_withAnIntArgument() {
        assertEquals("5", eval("((root load: \"Counter\") create: 5) count"));
    }

    @Test
    void constructor_argumentIsConvertedFromAString() {
        assertEquals("7", eval("((root load: \"Counter\") create: \"7\") count"));
    }

    @Test
    void staticMethod_isAFactoryOperation() {
        assertEquals("5", eval("((root load: \"Counter\") startingAt: 3 step: 2) count"));
    }

    @Test
    void staticMethod_withHiddenContextSeesTheSender() {
        assertEquals("SelfManagedCell", eval("((root load: \"Counter\") ownedBySender) owner"));
    }

    @Test
    void factoryOperation_thatThrows_isARuntimeErrorNamingTheSelector() {
        String message = error("(root load: \"Counter\") failing");
        assertTrue(message.contains("'failing'"), message);
        assertTrue(message.contains("no counters today"), message);
    }

    @Test
    void unknownFactoryOperation_isAnError() {
        assertEquals("unknown constructor or static operation: 'build'", error("(root load: \"Counter\") build"));
    }

    @Test
    void instanceMethod_isNotAFactoryOperation() {
        assertEquals("unknown constructor or static operation: 'count'", error("(root load: \"Counter\") count"));
    }

    @Test
    void staticMethod_isNotAnInstanceOperation() {
        assertEquals("unknown operation 'startingAt:step:' on Counter", error(NEW + "c startingAt: 1 step: 2"));
    }

    // ---- instance operations and conversions ----

    @Test
    void intParameter_takesANumber() {
        assertEquals("3", eval(NEW + "c add: 3. c count"));
    }

    @Test
    void intParameter_parsesAString() {
        assertEquals("5", eval(NEW + "c add: \"5\". c count"));
    }

    @Test
    void intParameter_acceptsAWholeNumberWithFractionZeros() {
        assertEquals("5", eval(NEW + "c add: 5.00. c count"));
    }

    @Test
    void intParameter_refusesAFraction() {
        assertEquals("argument 1 of 'add:' on Counter must be a whole number, got 2.5", error(NEW + "c add: 2.5"));
    }

    @Test
    void intParameter_refusesAnUnparseableString() {
        assertEquals("cannot parse 'x' as a number", error(NEW + "c add: \"x\""));
    }

    @Test
    void intParameter_refusesABoolean() {
        assertEquals("not a number: true", error(NEW + "c add: true"));
    }

    @Test
    void longParameter_takesANumberBeyondIntRange() {
        assertEquals("10000000000", eval(NEW + "c addLong: 10000000000. c count"));
    }

    @Test
    void longParameter_refusesAFraction() {
        assertEquals("argument 1 of 'addLong:' on Counter must be a whole number, got 2.5", error(NEW + "c addLong: 2.5"));
    }

    @Test
    void bigDecimalParameter_parsesAString() {
        assertEquals("12", eval(NEW + "c addNumber: \"12\". c count"));
    }

    @Test
    void doubleParameter_takesANumberAndTheResultComesBackAsANumber() {
        assertEquals("6.0", eval(NEW + "c add: 4. c scale: 1.5"));
    }

    @Test
    void stringParameter_takesANumberByItsPrintedForm() {
        assertEquals("2.50=0", eval(NEW + "c label: 2.50"));
    }

    @Test
    void stringParameter_takesABooleanByItsPrintedForm() {
        assertEquals("true=0", eval(NEW + "c label: true"));
    }

    @Test
    void stringParameter_refusesAnArray() {
        assertEquals("argument 1 of 'label:' on Counter must be a String, got Array", error(NEW + "c label: #(1)"));
    }

    @Test
    void booleanParameter_takesABoolean() {
        assertEquals("false", eval(NEW + "c negate: true"));
    }

    @Test
    void booleanParameter_refusesANumber() {
        assertEquals("not a boolean: 1", error(NEW + "c negate: 1"));
    }

    @Test
    void blockParameter_canBeCalledThroughTheContext() {
        assertEquals("4", eval(NEW + "c add: 3. c apply: [:n | n + 1]"));
    }

    @Test
    void blockParameter_refusesANumber() {
        assertEquals("not a block: 5", error(NEW + "c apply: 5"));
    }

    @Test
    void arrayParameter_takesAnArray() {
        assertEquals("6", eval(NEW + "c sum: #(1 2 3)"));
    }

    @Test
    void arrayParameter_refusesANumberNamingTheArrayClassAsPonderTalkShowsIt() {
        String message = error(NEW + "c sum: 5");
        assertTrue(message.startsWith("argument 1 of 'sum:' on Counter must be a"), message);
        assertTrue(message.endsWith(" Array, got Number"), message);
    }

    @Test
    void hashParameter_takesAHash() {
        assertEquals("[a, b]", eval(NEW + "c keysOf: #(\"a\" 1 \"b\" 2) asHash"));
    }

    @Test
    void hashParameter_refusesAnArrayNamingTheHashClassAsPonderTalkShowsIt() {
        String message = error(NEW + "c keysOf: #(1)");
        assertTrue(message.startsWith("argument 1 of 'keysOf:' on Counter must be a"), message);
        assertTrue(message.endsWith(" Hash, got Array"), message);
    }

    @Test
    void objectParameter_takesAnythingAsItIs() {
        assertEquals("[1, two]", eval(NEW + "c echo: #(1 \"two\")"));
        assertEquals("true", eval(NEW + "(c echo: c) == c"));
    }

    @Test
    void javaClassParameter_unwrapsTheManagedObject() {
        assertEquals("hello fred", eval(NEW + "c greet: c friend"));
    }

    @Test
    void javaClassParameter_refusesAnotherKind() {
        assertEquals("argument 1 of 'greet:' on Counter must be a Friend, got Number", error(NEW + "c greet: 3"));
    }

    @Test
    void binaryOperation_takesOneArgument() {
        assertEquals("10", eval(NEW + "c add: 7. c + 3"));
    }

    @Test
    void threeArguments_convertEachByItsType() {
        assertEquals("x5true", eval(NEW + "c join: \"x\" with: \"5\" and: true"));
    }

    @Test
    void fourArguments_convertEachByItsType() {
        assertEquals("s,2,0.5,1.50", eval(NEW + "c a: \"s\" b: 2 c: 0.5 d: \"1.50\""));
    }

    @Test
    void fiveArguments_convertEachByItsType() {
        assertEquals("10!", eval(NEW + "c a: 1 b: \"2\" c: 3 d: 4.0 e: \"!\""));
    }

    @Test
    void fiveArguments_badConversionNamesTheArgumentPosition() {
        assertEquals("argument 4 of 'a:b:c:d:e:' on Counter must be a whole number, got 4.5",
                error(NEW + "c a: 1 b: 2 c: 3 d: 4.5 e: \"!\""));
    }

    // ---- results ----

    @Test
    void voidMethod_answersTheReceiver() {
        assertEquals("true", eval(NEW + "(c add: 3) == c"));
    }

    @Test
    void voidMethod_answerCanBeCascaded() {
        assertEquals("5", eval(NEW + "((c add: 3) add: 2) count"));
    }

    @Test
    void nullResult_answersNil() {
        assertEquals("nil", eval(NEW + "c nothing"));
    }

    @Test
    void listResult_becomesAnArray() {
        assertEquals("Array", eval(NEW + "c list class"));
        assertEquals("[1, 2, 3]", eval(NEW + "c list"));
    }

    @Test
    void mapResult_becomesAHash() {
        assertEquals("{ a=\"1\" b=\"two\" }", eval(NEW + "c map"));
    }

    @Test
    void annotatedJavaResult_isWrappedAsAManagedObject() {
        assertEquals("Friend", eval(NEW + "c friend class"));
        assertEquals("fred", eval(NEW + "c friend name"));
    }

    @Test
    void hiddenContext_receiverIsTheManagedHandle() {
        assertEquals("true", eval(NEW + "c me == c"));
    }

    @Test
    void hiddenContext_subjectOfATopLevelStatementIsRoot() {
        assertEquals("true", eval(NEW + "c sender == root"));
    }

    @Test
    void managedObject_printsItsClassAndPath() {
        assertEquals("<Counter>", eval(NEW + "c"));
        assertEquals("<Counter root/c>", eval(NEW + "root at: \"c\" put: c. c"));
    }

    @Test
    void managedName_replacesTheJavaClassName() {
        assertEquals("Gadget", eval("(root load: \"Widget\") create class"));
    }

    @Test
    void commonOperations_areAnsweredByEveryManagedObject() {
        assertEquals("Counter", eval(NEW + "c class"));
        assertEquals("true", eval(NEW + "c self == c"));
        assertEquals("false", eval(NEW + "c != c"));
    }

    // ---- errors ----

    @Test
    void unknownSelector_isAnErrorNamingTheClass() {
        assertEquals("unknown operation 'frob' on Counter", error(NEW + "c frob"));
    }

    @Test
    void unknownSelector_onAManagedNameUsesThatName() {
        assertEquals("unknown operation 'frob' on Gadget", error("(root load: \"Widget\") create frob"));
    }

    @Test
    void unknownSelector_isReportedAtTheSelector() {
        error(NEW + "\nc   frob");
        assertEquals(new SourcePos("t.p2", 2, 5), errors.get(0).pos());
    }

    @Test
    void javaException_becomesAnErrorNamingTheSelectorAndTheCause() {
        String message = error(NEW + "c boom");
        assertTrue(message.contains("'boom'"), message);
        assertTrue(message.contains("kaput"), message);
        assertEquals(new SourcePos("t.p2", 1, NEW.length() + 3), errors.get(0).pos());
    }

    @Test
    void javaException_stopsTheRestOfTheUnit() {
        cell.run("t.p2", NEW + "c boom. root print: 1");
        assertEquals(List.of(), output);
    }

    @Test
    void javaException_leavesTheCellUsableForLaterUnits() {
        cell.run("t.p2", NEW + "root at: \"c\" put: c. c add: 2. c boom");
        errors.clear();
        assertEquals("3", eval("root/c add: 1. root/c count"));
    }

    @Test
    void javaException_insideAPolicyActionIsReportedAsAnActionError() {
        RunResult result = cell.run("t.p2", """
                root/event at: "go" put: (root/factory/event create).
                c := (root load: "Counter") create.
                p := root/factory/ecapolicy create.
                p event: root/event/go; action: [c boom]; action: [root print: "after"].
                p active: true.
                root/event/go create.
                root print: "raised"
                """);
        assertEquals(RunResult.Status.OK, result.status());
        assertEquals(List.of("after", "raised"), output);
        assertEquals(1, errors.size(), errors.toString());
        String message = errors.get(0).message();
        assertTrue(message.startsWith("ObligationPolicy: unhandled action error: "), message);
        assertTrue(message.contains("'boom'") && message.contains("kaput"), message);
    }

    @Test
    void doubleResult_notANumber_isAnErrorNamingTheSelectorNotAnEscapingException() {
        RunResult result = assertDoesNotThrow(() -> cell.run("t.p2", NEW + "c notANumber"));
        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status());
        assertEquals(1, errors.size(), errors.toString());
        assertTrue(errors.get(0).message().contains("'notANumber'"), errors.get(0).message());
    }

    @Test
    void doubleResult_infinite_isAnErrorNotAnEscapingException() {
        RunResult result = assertDoesNotThrow(() -> cell.run("t.p2", NEW + "c add: 1. c scale: 1e400"));
        assertEquals(RunResult.Status.RUNTIME_ERROR, result.status());
        assertEquals(1, errors.size(), errors.toString());
        assertTrue(errors.get(0).message().contains("'scale:'"), errors.get(0).message());
    }

    @Test
    void doubleResult_notANumberInsideAPolicyAction_isReportedNotThrownToTheEmbedder() {
        cell.run("boot.p2", """
                root/event at: "go" put: (root/factory/event create).
                c := (root load: "Counter") create.
                p := root/factory/ecapolicy create.
                p event: root/event/go; action: [c notANumber].
                p active: true.
                """);
        boolean raised = assertDoesNotThrow(() -> cell.raise("root/event/go"));
        assertTrue(raised);
        assertEquals(1, errors.size(), errors.toString());
        assertTrue(errors.get(0).message().startsWith("ObligationPolicy: unhandled action error: "), errors.get(0).message());
    }

    // ---- tables ----

    @Test
    void dispatchTable_isBuiltOncePerClass() {
        assertSame(ManagedClass.of(Counter.class), ManagedClass.of(Counter.class));
        assertSame(ManagedClass.factoryOf(Counter.class), ManagedClass.factoryOf(Counter.class));
        assertNotSame(ManagedClass.of(Counter.class), ManagedClass.factoryOf(Counter.class));
    }

    @Test
    void instanceTable_holdsInstanceMethodsAndTheCommonOperations() {
        ManagedClass type = ManagedClass.of(Counter.class);
        assertEquals("Counter", type.name());
        assertFalse(type.isFactory());
        assertTrue(type.selectors().containsAll(List.of("add:", "count", "+", "a:b:c:d:e:", "class", "self", "==", "!=")),
                type.selectors().toString());
        assertFalse(type.selectors().contains("create"));
        assertFalse(type.selectors().contains("startingAt:step:"));
    }

    @Test
    void factoryTable_holdsConstructorsAndStaticMethods() {
        ManagedClass factory = ManagedClass.factoryOf(Counter.class);
        assertTrue(factory.isFactory());
        assertTrue(factory.selectors().containsAll(List.of("create", "create:", "startingAt:step:", "ownedBySender")),
                factory.selectors().toString());
        assertFalse(factory.selectors().contains("count"));
    }

    @Test
    void selectors_areSortedAndReadOnly() {
        List<String> selectors = List.copyOf(ManagedClass.of(Counter.class).selectors());
        assertEquals(selectors.stream().sorted().collect(Collectors.toList()), selectors);
        assertThrows(UnsupportedOperationException.class, () -> ManagedClass.of(Counter.class).selectors().add("x"));
    }

    // ---- registration checks ----

    @Test
    void arityMismatch_isRejectedWhenTheCellIsBuilt() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> PolicyEngine.builder().register("Bad", Bad.class).build());
        assertTrue(e.getMessage().contains("'at:put:'"), e.getMessage());
    }

    @Test
    void arityMismatch_isRejectedWhenRegisteredLater() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> cell.register("Bad", Bad.class));
        assertTrue(e.getMessage().contains("'at:put:'"), e.getMessage());
        assertTrue(error("root load: \"Bad\"").startsWith("Load Managed Object - Adaptor for 'Bad' not found; "));
    }

    @Test
    void arityMismatch_unaryWithAnArgumentIsRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> cell.register("B", BadUnary.class));
        assertTrue(e.getMessage().contains("'size'"), e.getMessage());
    }

    @Test
    void arityMismatch_binaryWithTwoArgumentsIsRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> cell.register("B", BadBinary.class));
        assertTrue(e.getMessage().contains("'+'"), e.getMessage());
    }

    @Test
    void arityMismatch_onAConstructorIsRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> cell.register("B", BadConstructor.class));
        assertTrue(e.getMessage().contains("'create:'"), e.getMessage());
    }

    @Test
    void sameSelectorTwice_isRejected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> cell.register("T", Twice.class));
        assertTrue(e.getMessage().contains("'x'"), e.getMessage());
    }

    @Test
    void registeringAfterBuild_makesTheClassLoadable() {
        cell.register("Friend", Friend.class);
        assertEquals("Factory", eval("(root load: \"Friend\") class"));
    }
}
