package net.smc.core.host;

import net.smc.core.cell.Scheme;
import net.smc.core.cell.CellView;
import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Cell;
import net.smc.core.cell.CellBuilder;
import java.io.IOException;
import java.util.Objects;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.locks.Lock;
import java.util.function.Consumer;
import java.util.function.UnaryOperator;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.mission.Mission;
import net.smc.core.role.TaskProvider;
import net.smc.core.security.SigningIdentity;
import net.smc.core.security.SecureEndpoint;
import net.smc.core.security.SecureTransport;
import net.smc.core.security.TrustAnchor;
import net.smc.core.transport.udp.StatusResponder;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Scheduler;
import net.smc.core.transport.Transport;
import net.smc.core.transport.real.RealTimeScheduler;
import net.smc.core.transport.real.SystemClock;
import net.smc.core.transport.udp.UdpCounters;
import net.smc.core.transport.udp.UdpEventLoop;
import net.smc.core.transport.udp.UdpSettings;
import net.smc.core.transport.udp.UdpTransport;
import net.smc.policy.api.AuthMode;
import net.smc.policy.api.PolicyRepository;

/**
 * A {@link Cell} deployed on a real network: Netty UDP underneath, status queries answered
 * ({@link StatusResponder}), optionally authenticated ({@link SecureTransport}), the wall clock, and
 * one thread that every input of the cell runs on. What {@code smc node} runs, and what loopback
 * tests start several of in one JVM.
 *
 * <pre>{@code
 * try (CellHost host = CellHost.open(CellHost.settings("uav1", mission, description, repository)
 *         .udp(UdpSettings.defaults().withPort(4001)).commander(true))) {
 *     host.view();   // from any thread
 * }
 * }</pre>
 */
public final class CellHost implements AutoCloseable {
    private final ExecutorService thread;
    /** Where the cell's inputs run: its thread, holding the guard if the settings gave one. */
    private final Executor inputs;
    private final Lock guard;
    private final ScheduledExecutorService timer;
    private final UdpTransport udp;
    private final Transport transport;
    private final StatusResponder status;
    private final Cell cell;

    private CellHost(Settings s, UdpEventLoop loop) throws IOException {
        String name = "cell-" + s.vehicle;
        this.thread = Executors.newSingleThreadExecutor(r -> daemon(r, name));
        this.timer = Executors.newSingleThreadScheduledExecutor(r -> daemon(r, name + "-timer"));
        this.guard = s.guard;
        this.inputs = guard == null ? thread : r -> thread.execute(() -> guarded(r));
        Clock clock = s.clock == null ? new SystemClock() : s.clock;
        try {
            udp = loop == null ? UdpTransport.open(s.udp, inputs) : UdpTransport.open(s.udp, inputs, loop);
        } catch (IOException | RuntimeException e) {
            thread.shutdownNow();
            timer.shutdownNow();
            throw e;
        }
        if (s.identity != null) {   // session traffic and status queries before strangers' signed datagrams
            udp.setUrgent(d -> SecureTransport.isSessionTraffic(d) || StatusResponder.looksLikeQuery(d));
        }
        Cell[] made = new Cell[1];
        this.status = new StatusResponder(udp, () -> made[0] == null ? "{}" : made[0].view().toJson());
        Transport under = Objects.requireNonNull(s.wrap.apply(status), "the transport wrapper returned null");
        this.transport = s.identity == null ? under
                : new SecureTransport(under, SecureEndpoint.builder(s.identity, s.trust, clock).build());
        Scheduler realTime = new RealTimeScheduler(timer, inputs);
        double rate = s.rate;
        Scheduler scheduler = rate == 1 ? realTime
                : (delayMillis, task) -> {
                    Scheduler.checkDelay(delayMillis);
                    return realTime.schedule(Math.round(delayMillis / rate), task);
                };
        CellBuilder b = Cell.builder(s.vehicle, s.mission, s.description).transport(transport).clock(clock)
                .scheduler(scheduler).repository(s.repository).commander(s.commander)
                .seed(s.seed).trace(s.trace).output(s.output).tasks(s.tasks).auth(s.auth);
        if (s.scheme != null) {
            b.scheme(s.scheme);
        }
        this.cell = call(() -> {
            Cell c = b.build();
            made[0] = c;
            s.beforeStart.accept(c);
            c.start();
            s.afterStart.accept(c);
            return c;
        });
    }

    private void guarded(Runnable r) {
        guard.lock();
        try {
            r.run();
        } finally {
            guard.unlock();
        }
    }

    /** Starts a cell on its own UDP event loop. */
    public static CellHost open(Settings settings) throws IOException {
        return new CellHost(settings, null);
    }

    /** Starts a cell on a shared UDP event loop (many cells in one JVM). */
    public static CellHost open(Settings settings, UdpEventLoop loop) throws IOException {
        return new CellHost(settings, Objects.requireNonNull(loop, "loop"));
    }

    public static Settings settings(String vehicle, Mission mission, CapabilityDescription description,
                                    PolicyRepository repository) {
        return new Settings(vehicle, mission, description, repository);
    }

    /** The cell's view, taken on its thread. */
    public CellView view() {
        return call(cell::view);
    }

    /** Runs {@code action} on the cell's thread and waits for its answer (at most 10 s). */
    public <T> T call(Callable<T> action) {
        Future<T> f = thread.submit(guard == null ? action : () -> {
            guard.lock();
            try {
                return action.call();
            } finally {
                guard.unlock();
            }
        });
        try {
            return f.get(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for the cell's thread", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause().getMessage(), e.getCause());
        } catch (TimeoutException e) {
            f.cancel(true);
            throw new IllegalStateException("the cell's thread did not answer within 10 s", e);
        }
    }

    /** The cell; touch it only through {@link #call}. */
    public Cell cell() {
        return cell;
    }

    public StatusResponder status() {
        return status;
    }

    /** What the cell's UDP sockets have done so far (datagrams handed to the kernel, delivered ...). */
    public UdpCounters udpCounters() {
        return udp.counters();
    }

    /** Stops the cell, closes the network and ends its threads. */
    @Override
    public void close() {
        try {
            call(() -> {
                cell.stop();
                return null;
            });
        } catch (IllegalStateException ignored) {
            // closing anyway
        }
        transport.close();
        timer.shutdownNow();
        thread.shutdown();
        try {
            thread.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static Thread daemon(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        return t;
    }

    /** What a host needs; vehicle, mission, description and repository are required. */
    public static final class Settings {
        private final String vehicle;
        private final Mission mission;
        private final CapabilityDescription description;
        private final PolicyRepository repository;
        private UdpSettings udp = UdpSettings.defaults();
        private boolean commander;
        private Scheme scheme;
        private SigningIdentity identity;
        private TrustAnchor trust;
        private long seed = System.nanoTime();
        private Consumer<CellEvent> trace = e -> { };
        private Consumer<String> output = line -> { };
        private UnaryOperator<Transport> wrap = UnaryOperator.identity();
        private TaskProvider tasks = TaskProvider.NONE;
        private AuthMode auth = AuthMode.OFF;
        private Clock clock;
        private double rate = 1;
        private Lock guard;
        private Consumer<Cell> beforeStart = c -> { };
        private Consumer<Cell> afterStart = c -> { };

        private Settings(String vehicle, Mission mission, CapabilityDescription description, PolicyRepository repository) {
            this.vehicle = Objects.requireNonNull(vehicle, "vehicle");
            this.mission = Objects.requireNonNull(mission, "mission");
            this.description = Objects.requireNonNull(description, "description");
            this.repository = Objects.requireNonNull(repository, "repository");
        }

        public Settings udp(UdpSettings settings) {
            this.udp = Objects.requireNonNull(settings, "settings");
            return this;
        }

        public Settings commander(boolean commander) {
            this.commander = commander;
            return this;
        }

        public Settings scheme(Scheme scheme) {
            this.scheme = scheme;
            return this;
        }

        /** Authenticates with this key and credential, trusting {@code trust}; unauthenticated when not set. */
        public Settings security(SigningIdentity identity, TrustAnchor trust) {
            this.identity = Objects.requireNonNull(identity, "identity");
            this.trust = Objects.requireNonNull(trust, "trust");
            return this;
        }

        public Settings seed(long seed) {
            this.seed = seed;
            return this;
        }

        /** Receives every decision, on the cell's thread. */
        public Settings trace(Consumer<CellEvent> trace) {
            this.trace = Objects.requireNonNull(trace, "trace");
            return this;
        }

        /**
         * Puts a decorator between the network and the cell, under authentication: it gets the UDP
         * transport (with status queries already answered) and returns what the cell's security
         * layer, or the cell, uses. For fault injection on loopback (loss, partitions); none by
         * default. The decorator is called on the cell's thread and closed with the host.
         */
        public Settings wrap(UnaryOperator<Transport> wrap) {
            this.wrap = Objects.requireNonNull(wrap, "wrap");
            return this;
        }

        /** The vehicle's tasks (default none): see {@code CellBuilder#tasks}. */
        public Settings tasks(TaskProvider tasks) {
            this.tasks = Objects.requireNonNull(tasks, "tasks");
            return this;
        }

        /** The cell's authorisation mode (default OFF; DENY as deployed): see {@code CellBuilder#auth}. */
        public Settings auth(AuthMode mode) {
            this.auth = Objects.requireNonNull(mode, "auth");
            return this;
        }

        /**
         * The cell's clock instead of the system's, and how many of its milliseconds pass per wall
         * millisecond ({@code rate}; the cell's timers wait {@code delay / rate} wall milliseconds).
         * For a team that shares one mission clock, possibly running faster than the wall clock.
         *
         * @throws IllegalArgumentException when the rate is not a positive finite number
         */
        public Settings clock(Clock clock, double rate) {
            if (!(rate > 0) || Double.isInfinite(rate)) {
                throw new IllegalArgumentException("clock rate " + rate + " must be a positive finite number");
            }
            this.clock = Objects.requireNonNull(clock, "clock");
            this.rate = rate;
            return this;
        }

        /**
         * A lock every input of the cell holds while it runs (datagrams, timers, {@link #call}): for a
         * cell whose tasks share state with other threads, such as a simulated world stepped on a
         * thread of its own. None by default.
         */
        public Settings guard(Lock guard) {
            this.guard = Objects.requireNonNull(guard, "guard");
            return this;
        }

        /** Runs on the cell's thread after it is built and before it starts (to install objects in its engine). */
        public Settings beforeStart(Consumer<Cell> action) {
            this.beforeStart = Objects.requireNonNull(action, "action");
            return this;
        }

        /** Runs on the cell's thread right after it started. */
        public Settings afterStart(Consumer<Cell> action) {
            this.afterStart = Objects.requireNonNull(action, "action");
            return this;
        }

        /** Receives what policies print, on the cell's thread. */
        public Settings output(Consumer<String> output) {
            this.output = Objects.requireNonNull(output, "output");
            return this;
        }
    }
}
