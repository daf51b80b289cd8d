package net.smc.policy.runtime;

import net.smc.policy.api.PonderError;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.LongSupplier;
import java.util.random.RandomGenerator;
import net.smc.policy.api.AuthMode;
import net.smc.policy.api.Diagnostic;
import net.smc.policy.api.Limits;
import net.smc.policy.api.PolicyRepository;
import net.smc.policy.api.TeamLink;
import net.smc.policy.api.TimerScheduler;
import net.smc.policy.lang.IncludeResolver;
import net.smc.policy.lang.ParsedUnits;
import net.smc.policy.lang.SourcePos;
import net.smc.policy.lang.SyntaxError;
import net.smc.policy.lang.Unit;

/**
 * The state of one self-managed cell's policy engine: the root domain, the registry of loadable
 * classes, event delivery, authorisation, and the injected output, error reporter, clock and
 * random source. Not thread-safe: a cell runs on one logical thread. Embedders use
 * {@link net.smc.policy.PolicyEngine}.
 */
public final class CellRuntime {
    /**
     * Configuration given by the embedding application.
     *
     * @param classes the loadable classes beyond the built-in kinds (the standard objects among them), in order
     * @param xml     parses XML text into a PonderTalk value ({@code "..." asXML})
     */
    public record Config(Consumer<String> output, Consumer<Diagnostic> errors, AuthMode auth, LongSupplier clock,
                         RandomGenerator random, Limits limits, PolicyRepository repository,
                         Map<String, Class<?>> classes, TimerScheduler scheduler, List<String> arguments,
                         Function<String, Object> xml, ParsedUnits parsedUnits) {
    }

    private final Config config;
    private final Interpreter interpreter = new Interpreter(this);
    private final Root root;
    private final LoadableClasses loadable = new LoadableClasses();
    private final UnitFiles files;
    private final Authoriser authoriser;
    private final ErrorReporter errors;
    private final List<Consumer<? super ManagedObject>> creationListeners = new ArrayList<>();
    private boolean booting = true;
    private TeamLink teamLink = TeamLink.NONE;
    private long attachCounter;
    /** Bumped on every change that can change what the policies decide: see {@link #policyVersion()}. */
    private long policyVersion;
    private Integer exitStatus;
    /** The status {@link #stop} gave, or -1; set from any thread, read by running executions. */
    private volatile int stopStatus = -1;

    public CellRuntime(Config config) {
        this.config = config;
        this.files = new UnitFiles(config.repository(), config.limits().maxUnitChars());
        this.errors = new ErrorReporter(config.errors(), config.limits().maxErrorsPerRun());
        this.authoriser = config.auth() == AuthMode.OFF ? null : new Authoriser(this, config.auth());
        config.classes().forEach(this::register);
        this.root = new Root(this);
        Domain factory = new Domain(this);
        factory.put("domain", LoadableClasses.factoryFor(Domain.class));
        factory.put("event", LoadableClasses.factoryFor(EventTemplate.class));
        factory.put("ecapolicy", LoadableClasses.factoryFor(ObligationPolicy.class));
        factory.put("authpolicy", LoadableClasses.factoryFor(AuthorisationPolicy.class));
        root.put("factory", factory);
        root.put("event", new Domain(this));
        root.put("policy", new Domain(this));
    }

    /** Makes a class loadable with {@code root load: "name"}; checks its annotations now. */
    public void register(String name, Class<?> type) {
        loadable.register(name, type);
    }

    /** The factory of a registered class ({@code root load:}). */
    ManagedObject load(String name) {
        return loadable.load(name);
    }

    /** A new domain that also answers the {@code @Op} operations of {@code extension}, which run on it. */
    public Domain newDomainWith(Object extension) {
        return new Domain(this, ManagedClass.withOperationsOf(Domain.class, extension));
    }

    public Root root() {
        return root;
    }

    public Interpreter interpreter() {
        return interpreter;
    }

    public Limits limits() {
        return config.limits();
    }

    /** Parses XML text into a PonderTalk value, as the embedding engine configured. */
    Object parseXml(String text) {
        return config.xml().apply(text);
    }

    public LongSupplier clock() {
        return config.clock();
    }

    public RandomGenerator random() {
        return config.random();
    }

    /** The arguments given after the files ({@code smc run FILE -- a b c}), for {@code root argsAsArray}. */
    public List<String> arguments() {
        return config.arguments();
    }

    /**
     * Runs {@code task} after {@code delayMillis} on the cell's scheduler, as one run of its own: a
     * {@link PonderError} it throws is reported, {@code root exit} ends the cell, and nothing runs
     * once the cell has exited.
     *
     * @return an action that calls the task off
     */
    public Runnable schedule(long delayMillis, Runnable task) {
        return config.scheduler().schedule(delayMillis, () -> {
            if (exitStatus() != null) {
                return;
            }
            try {
                task.run();
            } catch (PonderError e) {
                report(new Diagnostic(e.pos(), e.getMessage()));
            } catch (StackOverflowError e) {
                report(new Diagnostic(null, "stack exhausted in a timer; lower the nesting or the call depth limit"));
            } catch (ExitRequest exit) {
                exitStatus = exit.status();
            }
        });
    }

    /** The status {@code root exit} gave inside a scheduled task, or that {@link #stop} gave, or {@code null}. */
    public Integer exitStatus() {
        if (exitStatus == null && stopStatus >= 0) {
            return stopStatus;
        }
        return exitStatus;
    }

    /**
     * Asks the cell to stop; callable from any thread (a signal handler's, say). Whatever the cell
     * runs (a unit, an event's policies, a timer) ends within {@link Limits#CLOCK_CHECK_INTERVAL}
     * sends or at its next top-level statement, as if {@code root exit: status} had run there, and
     * nothing runs after it.
     *
     * @throws IllegalArgumentException when {@code status} is negative
     */
    public void stop(int status) {
        if (status < 0) {
            throw new IllegalArgumentException("stop status is " + status + "; it must be 0 or more");
        }
        stopStatus = status;
    }

    /** The status {@link #stop} gave, or -1 when the cell was not asked to stop. */
    int stopStatus() {
        return stopStatus;
    }

    /** The names {@code root load:} knows, sorted. */
    public java.util.Set<String> loadableNames() {
        return loadable.names();
    }

    /**
     * The text of a file that a unit names (resolved as {@code read:} resolves it: against the
     * folder of the file {@code fromSource}, then the repository; also a {@code policy:} URI).
     *
     * @throws PonderError {@code cannot read 'x': file not found}
     */
    public String readText(String name, String fromSource) {
        return files.readText(name, fromSource);
    }

    /** Runs PonderTalk text as a nested unit of {@code ex} with fresh variables; errors propagate. */
    public Object evaluate(Execution ex, String source, String text) {
        return runNested(ex, source, text, null);
    }

    Authoriser authoriser() {
        return authoriser;
    }

    /** How the standard objects reach other cells of the team; {@code TeamLink.NONE} until the owner sets one. */
    public TeamLink teamLink() {
        return teamLink;
    }

    public void teamLink(TeamLink link) {
        this.teamLink = Objects.requireNonNull(link, "link");
    }

    /** Whether boot units are still running (authorisation then defaults to allow). */
    public boolean booting() {
        return booting;
    }

    /** Ends the boot phase: from now on the configured default decision applies. */
    public void endBoot() {
        booting = false;
        if (authoriser != null) {
            authoriser.invalidate();
            policiesChanged();
        }
    }

    /** Domain membership changed: with authorisation on, what the authorisation policies allow may have. */
    void membershipChanged() {
        if (authoriser != null) {
            authoriser.invalidate();
            policiesChanged();
        }
    }

    /**
     * A number that grows whenever what this cell's policies decide may have changed: a policy
     * created, enabled or disabled, given an event, a condition or an action, attached or detached
     * (so also withdrawn), an authorisation policy changed, or, with authorisation on, domain
     * membership or the end of the boot phase. Equal numbers mean the same policies, configured
     * the same way; the decisions may still differ where a condition reads other state.
     */
    public long policyVersion() {
        return policyVersion;
    }

    /** Notes a change that may change what the policies decide. */
    void policiesChanged() {
        policyVersion++;
    }

    long nextAttachOrder() {
        return ++attachCounter;
    }

    /** Prints one line on the cell's output. */
    void print(String line) {
        config.output().accept(line);
    }

    /** Reports an error to the cell's error reporter (and to every listener added with {@link #listen}). */
    public void report(Diagnostic diagnostic) {
        errors.report(diagnostic);
    }

    /**
     * Reports an error of a run, unless the run has already reported {@link Limits#maxErrorsPerRun}:
     * then it is only counted, and {@link #finish} reports the count.
     */
    void report(Execution ex, Diagnostic diagnostic) {
        if (ex.admitError()) {
            report(diagnostic);
        }
    }

    /** Ends a run: reports how many of its errors were suppressed, if any were. */
    public void finish(Execution ex) {
        errors.finish(ex);
    }

    /** Also gives every diagnostic to {@code listener} until {@link #unlisten} removes it. */
    public void listen(Consumer<Diagnostic> listener) {
        errors.listen(listener);
    }

    public void unlisten(Consumer<Diagnostic> listener) {
        errors.unlisten(listener);
    }

    /**
     * Tells {@code listener} of every obligation and authorisation policy created from now on,
     * however it was created (a factory, {@code root load:}, Java), until {@link #unlistenCreations}.
     */
    public void listenCreations(Consumer<? super ManagedObject> listener) {
        creationListeners.add(listener);
    }

    public void unlistenCreations(Consumer<? super ManagedObject> listener) {
        creationListeners.remove(listener);
    }

    void created(ManagedObject policy) {
        policiesChanged();
        for (Consumer<? super ManagedObject> listener : List.copyOf(creationListeners)) {
            listener.accept(policy);
        }
    }

    /**
     * Sends a message from Java as {@code subject} would: when authorisation is on, the send is
     * checked from subject to receiver (unless the subject is root).
     *
     * @throws PonderError when the receiver does not understand, the send is denied, or it fails
     */
    public Object sendAs(Object subject, Object receiver, String selector, Object[] args) {
        Execution ex = new Execution(this, subject);
        return interpreter.send(ex, receiver, selector, args, null);
    }

    /** A new run whose statements have root as their source. */
    public Execution newExecution() {
        return new Execution(this, root);
    }

    /** A new run whose statements have {@code source} (root, a policy, a managed object) as their source. */
    public Execution newExecution(Object source) {
        return new Execution(this, source);
    }

    /**
     * Delivers an event as if raised at {@code start}: to its policies and observers and those of
     * every domain above it. Counts as one nested call against the call depth limit, so that
     * forwarding loops end with an error.
     */
    public void deliverAt(Execution ex, ManagedObject start, EventTemplate template, Object[] values) {
        if (ex.depth >= limits().maxCallDepth()) {
            throw new PonderError("call depth limit of " + limits().maxCallDepth() + " exceeded");
        }
        Object saved = ex.source;
        ex.depth++;
        ex.source = start;
        try {
            deliver(ex, template, values);
        } finally {
            ex.source = saved;
            ex.depth--;
        }
    }

    /**
     * Sends a message within a running {@code ex} as {@code subject} would (checked when
     * authorisation is on); counts as one nested call against the call depth limit.
     */
    public Object sendWithin(Execution ex, Object subject, Object receiver, String selector, Object[] args) {
        if (ex.depth >= limits().maxCallDepth()) {
            throw new PonderError("call depth limit of " + limits().maxCallDepth() + " exceeded");
        }
        Object saved = ex.source;
        ex.depth++;
        ex.source = subject;
        try {
            return interpreter.send(ex, receiver, selector, args, null);
        } finally {
            ex.source = saved;
            ex.depth--;
        }
    }

    /**
     * Checks a unit; syntax errors are reported. The file, when given, anchors includes and reads.
     * The unit keeps its text, not its tree: {@link #run} parses each statement again as it runs it.
     */
    public Unit parse(String source, String text, Path file) {
        if (file != null) {
            files.remember(source, file);
        }
        if (text.length() > config.limits().maxUnitChars()) {
            SyntaxError tooLong = new SyntaxError(new SourcePos(source, 1, 1), "unit of " + text.length()
                    + " characters is longer than the limit of " + config.limits().maxUnitChars());
            report(new Diagnostic(tooLong.pos(), tooLong.message()));
            return Unit.refused(source, tooLong);
        }
        return files.parse(source, text, config.parsedUnits(), e -> report(new Diagnostic(e.pos(), e.message())));
    }

    /** The variables of a shell session, kept across its inputs. */
    public static final class Variables {
        private Map<String, Object> values = new LinkedHashMap<>();

        /** A variable's value, or {@code null}. */
        public Object get(String name) {
            return values.get(name);
        }
    }

    /**
     * Runs a checked unit (which must have no syntax errors) in a run of its own, statement by
     * statement: each is parsed, compiled and run in turn and then dropped, so a large unit never
     * has its whole tree in memory. A runtime error is reported and ends the unit;
     * {@link ExitRequest} passes through.
     *
     * @return the value of the last statement, or {@code null} when the unit failed
     */
    public Object run(Unit unit, Variables variables) {
        Execution ex = newExecution();
        VariableFrame frame = new VariableFrame(ex, variables == null ? Map.of() : variables.values);
        try {
            return runStatements(unit, frame);
        } catch (PonderError e) {
            report(new Diagnostic(e.pos(), e.getMessage()));
            return null;
        } catch (StackOverflowError e) {
            report(new Diagnostic(null, "stack exhausted while running " + unit.source()
                    + "; lower the nesting or the call depth limit"));
            return null;
        } finally {
            finish(ex);
            if (variables != null) {
                variables.values = frame.kept();
            }
        }
    }

    /**
     * Runs a unit nested in a running one ({@code readString:}, {@code read:}); errors propagate to
     * it. Counts as one nested call against the call depth limit, so that a unit that reads itself
     * ends with that error, as a block that calls itself does.
     */
    Object runNested(Execution ex, String source, String text, Path file) {
        ex.checkCallDepth();
        Unit unit = parse(source, text, file);
        if (unit.hasErrors()) {
            throw new PonderError("cannot run '" + source + "': " + unit.errors().size() + " syntax error"
                    + (unit.errors().size() == 1 ? "" : "s"));
        }
        ex.enterCall();
        try {
            return runStatements(unit, new VariableFrame(ex, Map.of()));
        } finally {
            ex.leaveCall();
        }
    }

    /** Runs a unit's statements in order in {@code frame}; answers the last one's value (nil for none). */
    private Object runStatements(Unit unit, VariableFrame frame) {
        Object[] last = {net.smc.policy.api.Nil.NIL};
        unit.forEachStatement(statement -> last[0] = interpreter.run(statement, frame));
        return last[0];
    }

    /** Reads the file or policy URI {@code name}, relative to the folder of {@code fromSource}; null when there is none. */
    IncludeResolver.Included readFile(String name, String fromSource) {
        return files.read(name, fromSource);
    }

    /** Converts a Java value to a PonderTalk value (ints to numbers, lists to arrays, maps to hashes ...). */
    public static Object fromJava(Object value) {
        return Converter.fromJava(value);
    }

    /** Resolves a path string: absolute when it starts with '/', else from root ({@code root/} optional). */
    public Object resolve(String path) {
        return Paths.resolve(root, path);
    }

    /**
     * Delivers an event synchronously: to the policies attached at its source and at every domain
     * above it, each node once, in the order the policies were attached.
     */
    void deliver(Execution ex, EventTemplate template, Object[] values) {
        Event event = new Event(template, values);
        Object source = ex.source;
        if (source == root || !(source instanceof ManagedObject start)) {
            for (ObligationPolicy policy : root.policiesFor(template)) {
                policy.fire(ex, event);
            }
            root.notifyObservers(ex, template, values);
            return;
        }
        List<ManagedObject> nodes = new ArrayList<>();
        nodes.add(start);
        for (int i = 0; i < nodes.size(); i++) {
            for (Domain parent : nodes.get(i).parents()) {
                if (!nodes.contains(parent)) {
                    nodes.add(parent);
                }
            }
        }
        for (ManagedObject node : nodes) {
            for (ObligationPolicy policy : node.policiesFor(template)) {
                policy.fire(ex, event);
            }
            node.notifyObservers(ex, template, values);
        }
    }
}
