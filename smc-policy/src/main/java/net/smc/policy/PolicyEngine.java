package net.smc.policy;

import net.smc.policy.api.TimerScheduler;
import net.smc.policy.api.PolicyRepository;
import net.smc.policy.api.Limits;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.api.AuthMode;
import net.smc.policy.api.DomainHandle;
import net.smc.policy.api.EventHandle;
import net.smc.policy.api.Handle;
import net.smc.policy.api.TeamLink;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.OptionalInt;
import java.util.Random;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import java.util.random.RandomGenerator;
import net.smc.policy.lang.ParsedUnits;
import net.smc.policy.lang.SourceFiles;
import net.smc.policy.lang.Unit;
import net.smc.policy.runtime.CellRuntime;
import net.smc.policy.runtime.Domain;
import net.smc.policy.runtime.EventTemplate;
import net.smc.policy.runtime.Execution;
import net.smc.policy.runtime.ExitRequest;
import net.smc.policy.runtime.ManagedObject;
import net.smc.policy.runtime.TeamArrivals;
import net.smc.policy.api.PonderError;
import net.smc.policy.runtime.Values;
import net.smc.policy.stdlib.StandardObjects;

/**
 * Start here: one self-managed cell's policy engine, embeddable on its own. It runs PonderTalk
 * units, holds managed objects in domains, delivers events to obligation policies and checks
 * authorisation policies. Output, errors, clock and randomness are given by the caller; the cell
 * never prints, sleeps or reads the wall clock by itself. Not thread-safe: use it from one thread
 * (or one executor) at a time.
 *
 * <pre>{@code
 * List<String> lines = new ArrayList<>();
 * List<Diagnostic> errors = new ArrayList<>();
 * PolicyEngine cell = PolicyEngine.builder().output(lines::add).errors(errors::add).build();
 * cell.run("boot.p2", """
 *     root/event at: "alarm" put: (root/factory/event create: #("level")).
 *     p := root/factory/ecapolicy create.
 *     p event: root/event/alarm; condition: [:level | level > 5]; action: [:level | root print: level].
 *     p active: true.
 *     """);
 * cell.raise("root/event/alarm", 7);   // lines is now [7]
 * }</pre>
 */
public final class PolicyEngine {
    private final CellRuntime runtime;
    private final TimerQueue timers;
    private Integer exitStatus;

    private PolicyEngine(CellRuntime runtime, TimerQueue timers) {
        this.runtime = runtime;
        this.timers = timers;
    }

    public static Builder builder() {
        return new Builder();
    }

    /** Settings of a new cell; every one has a default. */
    public static final class Builder {
        private Consumer<String> output = line -> { };
        private Consumer<Diagnostic> errors = d -> { };
        private AuthMode auth = AuthMode.OFF;
        private LongSupplier clock = () -> 0L;
        private RandomGenerator random = new Random(0);
        private Limits limits = Limits.DEFAULT;
        private PolicyRepository repository;
        private TimerScheduler scheduler;
        private List<String> arguments = List.of();
        private final Map<String, Class<?>> classes = new LinkedHashMap<>();
        private ParsedUnits parsedUnits;

        /**
         * Where timers ({@code root load: "Timer"}) wait (default: a {@link TimerQueue} on the
         * cell's clock that the owner drives through {@link PolicyEngine#timers()}).
         */
        public Builder scheduler(TimerScheduler timerScheduler) {
            this.scheduler = Objects.requireNonNull(timerScheduler, "scheduler");
            return this;
        }

        /** The user's arguments, answered by {@code root argsAsArray} and {@code root argsAsHash} (default: none). */
        public Builder arguments(List<String> userArguments) {
            this.arguments = List.copyOf(userArguments);
            return this;
        }

        /** Where {@code root print:} lines go (default: nowhere). */
        public Builder output(Consumer<String> lineSink) {
            this.output = Objects.requireNonNull(lineSink, "output");
            return this;
        }

        /** Where errors go (default: nowhere). */
        public Builder errors(Consumer<Diagnostic> reporter) {
            this.errors = Objects.requireNonNull(reporter, "errors");
            return this;
        }

        /** Authorisation checking and its default decision (default: off). */
        public Builder auth(AuthMode mode) {
            this.auth = Objects.requireNonNull(mode, "auth");
            return this;
        }

        /** The clock, in milliseconds since the epoch (default: always 0). */
        public Builder clock(LongSupplier epochMillis) {
            this.clock = Objects.requireNonNull(epochMillis, "clock");
            return this;
        }

        /** The random source of {@code Number random} (default: seeded with 0). */
        public Builder random(RandomGenerator source) {
            this.random = Objects.requireNonNull(source, "random");
            return this;
        }

        public Builder limits(Limits bounds) {
            this.limits = Objects.requireNonNull(bounds, "limits");
            return this;
        }

        /** The policy repository that {@code policy:} URIs and includes resolve against. */
        public Builder repository(PolicyRepository repo) {
            this.repository = repo;
            return this;
        }

        /**
         * Shares the parse of small units with the other cells of this process given the same
         * {@link ParsedUnits} (default: none, every unit is parsed). Each cell still runs every
         * statement; a simulation of many cells in one process saves the parsing of identical text.
         */
        public Builder parsedUnits(ParsedUnits shared) {
            this.parsedUnits = shared;
            return this;
        }

        /** Makes a managed-object class loadable as {@code root load: "name"}. */
        public Builder register(String name, Class<?> type) {
            classes.put(Objects.requireNonNull(name, "name"), Objects.requireNonNull(type, "type"));
            return this;
        }

        public PolicyEngine build() {
            TimerQueue queue = scheduler == null ? new TimerQueue(clock) : null;
            Map<String, Class<?>> loadable = new LinkedHashMap<>(StandardObjects.classes());
            loadable.putAll(classes);
            return new PolicyEngine(new CellRuntime(new CellRuntime.Config(output, errors, auth, clock, random, limits,
                    repository, Collections.unmodifiableMap(loadable), scheduler == null ? queue : scheduler, arguments,
                    StandardObjects::parseXml, parsedUnits)), queue);
        }
    }

    /** Runs a unit of PonderTalk text with fresh variables. Errors go to the error reporter. */
    public RunResult run(String sourceName, String text) {
        return run(sourceName, text, null, null);
    }

    /** Runs a file as one unit; its name in diagnostics is the path as given. */
    public RunResult runFile(Path file) {
        String text;
        try {
            text = SourceFiles.read(file, runtime.limits().maxUnitChars());
        } catch (IOException | java.io.UncheckedIOException e) {
            Diagnostic cannotRead = new Diagnostic(null, file + ": cannot read: " + e.getMessage());
            runtime.report(cannotRead);
            return new RunResult(RunResult.Status.RUNTIME_ERROR, null, List.of(cannotRead));
        }
        return run(file.toString(), text, file, null);
    }

    /**
     * Runs text that came from {@code file} (which anchors its {@code include}s and {@code read:}s)
     * under the name {@code sourceName}, with fresh variables.
     */
    public RunResult run(String sourceName, String text, Path file) {
        return run(sourceName, text, file, null);
    }

    /** Runs the repository file a {@code policy:} URI names, with fresh variables. */
    public RunResult load(String uri) {
        return run("load", "root read: \"" + uri.replace("\"", "\\\"") + "\"");
    }

    /**
     * The cell's own timer queue, when it was built without a {@link Builder#scheduler}: run
     * {@link TimerQueue#runDue()} on the cell's thread when its clock reaches
     * {@link TimerQueue#nextDue()}.
     *
     * @throws IllegalStateException when the cell was given a scheduler of its own
     */
    public TimerQueue timers() {
        if (timers == null) {
            throw new IllegalStateException("this cell was given a scheduler; drive that one");
        }
        return timers;
    }

    /** Whether the cell has exited, by a unit or by a timer's event. */
    private boolean exited() {
        if (exitStatus == null && runtime.exitStatus() != null) {
            exitStatus = runtime.exitStatus();
        }
        return exitStatus != null;
    }

    private RunResult run(String sourceName, String text, Path file, CellRuntime.Variables variables) {
        if (exited()) {
            return new RunResult(RunResult.Status.EXITED, null, List.of());
        }
        List<Diagnostic> seen = new ArrayList<>();
        Consumer<Diagnostic> listener = seen::add;
        runtime.listen(listener);
        try {
            Unit unit = runtime.parse(sourceName, text, file);
            if (unit.hasErrors()) {
                return new RunResult(RunResult.Status.SYNTAX_ERROR, null, seen);
            }
            Object value = runtime.run(unit, variables);
            return value == null ? new RunResult(RunResult.Status.RUNTIME_ERROR, null, seen)
                    : new RunResult(RunResult.Status.OK, value, seen);
        } catch (ExitRequest exit) {
            exitStatus = exit.status();
            return new RunResult(RunResult.Status.EXITED, null, seen);
        } finally {
            runtime.unlisten(listener);
        }
    }

    /**
     * Sends a message from Java on behalf of {@code subject} (a managed object standing for, say,
     * a collaborating role): with authorisation on, the send is checked from that subject to the
     * receiver at all four enforcement points, as if a policy of the subject had sent it.
     *
     * @throws PonderError when the receiver does not understand the selector, the send is denied
     *                     ({@code Ponder2AuthorizationException: selector}), or the operation fails
     */
    public Object sendAs(Object subject, Object receiver, String selector, Object... args) {
        if (exited()) {
            throw new PonderError("the cell has exited");
        }
        Object[] converted = new Object[args.length];
        for (int i = 0; i < args.length; i++) {
            converted[i] = CellRuntime.fromJava(args[i]);
        }
        try {
            return runtime.sendAs(subject, receiver, selector, converted);
        } catch (ExitRequest exit) {
            exitStatus = exit.status();
            throw new PonderError("the cell has exited");
        }
    }

    /**
     * Connects the cell's standard objects to the other cells of its team ({@code EventForwarder
     * forwardTo: "/team/<cell>/<path>"}, {@code PonderTalk create: "/team/<cell>"}); the owner of a
     * team cell sets it once, before the cell takes input.
     */
    public void teamLink(TeamLink link) {
        runtime.teamLink(link);
    }

    /** Where events and PonderTalk text from other cells enter this cell, under its authorisation policies. */
    public TeamArrivals arrivals() {
        return new TeamArrivals(runtime);
    }

    /** A shell session: units whose variables persist from one to the next. */
    public final class Session {
        private final CellRuntime.Variables variables = new CellRuntime.Variables();

        public RunResult run(String sourceName, String text) {
            return PolicyEngine.this.run(sourceName, text, null, variables);
        }

        /** A variable's value, or {@code null} if it is not set. */
        public Object variable(String name) {
            return variables.get(name);
        }
    }

    public Session session() {
        return new Session();
    }

    /** Ends the boot phase: authorisation now applies the configured default decision. */
    public void endBoot() {
        runtime.endBoot();
    }

    /** Registers a managed-object class after the cell was built. */
    public void register(String name, Class<?> type) {
        runtime.register(name, type);
    }

    /**
     * The policy version: a number that grows whenever what this cell's policies decide may have
     * changed (a policy loaded or created, enabled, disabled, withdrawn or reconfigured, an
     * authorisation policy changed, or, with authorisation on, domain membership). A caller that
     * remembers a decision of the policies can keep it while the version stays the same; decisions
     * whose conditions read other state (a counter, the time) need a bound of their own.
     */
    public long policyVersion() {
        return runtime.policyVersion();
    }

    /** The root domain. */
    public DomainHandle root() {
        return runtime.root();
    }

    /** A new, empty domain, in no domain yet. */
    public DomainHandle newDomain() {
        return new Domain(runtime);
    }

    /**
     * A new, empty domain that also answers the {@link net.smc.policy.api.Op} operations of the Java
     * object {@code operations} (which win over the domain's own), named as its class is
     * ({@link net.smc.policy.api.Managed}): a domain that paths run through and that has operations of its own.
     */
    public DomainHandle newDomain(Object operations) {
        return runtime.newDomainWith(Objects.requireNonNull(operations, "operations"));
    }

    /** A new event template with these attribute names, in no domain yet. */
    public EventHandle newEventTemplate(List<String> attributeNames) {
        return new EventTemplate(runtime, attributeNames);
    }

    /**
     * Tells {@code listener} of every policy created from now on (by a factory, {@code root load:} or
     * Java), until {@link #unlistenCreations}.
     */
    public void listenCreations(Consumer<? super Handle> listener) {
        runtime.listenCreations(listener);
    }

    public void unlistenCreations(Consumer<? super Handle> listener) {
        runtime.unlistenCreations(listener);
    }

    /**
     * The object at a path such as {@code root/event/alarm} or {@code /event/alarm}.
     *
     * @throws PonderError {@code path not found '...'}
     */
    public Object resolve(String path) {
        return runtime.resolve(path);
    }

    /**
     * Raises an event of the template at {@code templatePath} from Java, with root as its source;
     * Java values convert as for managed-object results (ints to numbers, lists to arrays ...).
     * Errors in policies are reported, not thrown.
     *
     * @return {@code false} when the event could not be raised (the error was reported)
     */
    public boolean raise(String templatePath, Object... values) {
        EventHandle template;
        try {
            template = template(templatePath);
        } catch (PonderError e) {
            runtime.report(new Diagnostic(null, "raise " + templatePath + ": " + e.getMessage()));
            return false;
        }
        return raise(template, values);
    }

    /**
     * The event template at a path, for raising events without resolving the path each time.
     *
     * @throws PonderError when there is nothing at the path or it is not an event template
     */
    public EventHandle template(String path) {
        Object found = runtime.resolve(path);
        if (!(found instanceof EventTemplate t)) {
            throw new PonderError("'" + path + "' is a " + Values.className(found) + ", not an EventTemplate");
        }
        return t;
    }

    /** Raises an event of a template from Java, as {@link #raise(String, Object...)} does. */
    public boolean raise(EventHandle template, Object... values) {
        if (exited()) {
            return false;
        }
        try {
            Object[] converted = new Object[values.length];
            for (int i = 0; i < values.length; i++) {
                converted[i] = CellRuntime.fromJava(values[i]);
            }
            Execution ex = runtime.newExecution();
            try {
                ((EventTemplate) template).raise(ex, converted);
            } finally {
                runtime.finish(ex);
            }
            return true;
        } catch (PonderError e) {
            runtime.report(new Diagnostic(e.pos(), "raise: " + e.getMessage()));
            return false;
        } catch (StackOverflowError e) {
            runtime.report(new Diagnostic(null, "raise: stack exhausted; lower the nesting or the call depth limit"));
            return false;
        } catch (ExitRequest exit) {
            exitStatus = exit.status();
            return false;
        }
    }

    /**
     * Asks the cell to stop, from any thread: what it is running (a unit, an event's policies, a
     * timer) ends within {@link net.smc.policy.api.Limits#CLOCK_CHECK_INTERVAL} sends or at its next
     * top-level statement, as if {@code root exit: status} had run there; then {@link #exitStatus()}
     * is {@code status} and the cell runs nothing more.
     *
     * @throws IllegalArgumentException when {@code status} is negative
     */
    public void stop(int status) {
        runtime.stop(status);
    }

    /** The status given to {@code root exit} (or to {@link #stop}), once it has run. */
    public OptionalInt exitStatus() {
        exited();
        return exitStatus == null ? OptionalInt.empty() : OptionalInt.of(exitStatus);
    }

    /** The class name PonderTalk shows for a value ({@code Number}, {@code Domain}, a managed class's name ...). */
    public static String className(Object value) {
        return Values.className(value);
    }

    /** The printed form of a value, as {@code root print:} shows it. */
    public static String print(Object value) {
        return Values.print(value);
    }

    /** The engine behind the facade, for layers that build on it (the core's Role-Manager, say). */
    public CellRuntime runtime() {
        return runtime;
    }

    /** Wraps a Java object with {@link net.smc.policy.api.Op} annotations as a managed object. */
    public static Handle manage(Object javaObject) {
        return ManagedObject.wrap(javaObject);
    }
}
