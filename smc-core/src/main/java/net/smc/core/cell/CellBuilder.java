package net.smc.core.cell;

import java.util.Objects;
import java.util.function.Consumer;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.comm.SenderSettings;
import net.smc.core.message.SharedDecodes;
import net.smc.core.mission.Mission;
import net.smc.core.role.TaskProvider;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Scheduler;
import net.smc.core.transport.Transport;
import net.smc.policy.api.AuthMode;
import net.smc.policy.api.PolicyRepository;
import net.smc.policy.lang.ParsedUnits;

/** Collects what a {@link Cell} needs ({@link Cell#builder}); transport, clock, scheduler and repository are required. */
public final class CellBuilder {
    final String vehicle;
    final Mission mission;
    final CapabilityDescription description;
    Transport transport;
    Clock clock;
    Scheduler scheduler;
    PolicyRepository repository;
    ParsedUnits parsedUnits;
    SharedDecodes sharedDecodes;
    boolean commander;
    Scheme scheme;
    Timing timing;
    long seed;
    Consumer<CellEvent> trace = e -> { };
    Consumer<String> output = line -> { };
    SenderSettings senderSettings;
    TaskProvider tasks = TaskProvider.NONE;
    AuthMode auth = AuthMode.OFF;

    CellBuilder(String vehicle, Mission mission, CapabilityDescription description) {
        this.vehicle = Objects.requireNonNull(vehicle, "vehicle");
        this.mission = Objects.requireNonNull(mission, "mission");
        this.description = Objects.requireNonNull(description, "description");
        if (!description.vehicle().equals(vehicle)) {
            throw new IllegalArgumentException("capability description of '" + description.vehicle()
                    + "' given to cell '" + vehicle + "'; a cell describes its own vehicle");
        }
    }

    public CellBuilder transport(Transport transport) {
        this.transport = Objects.requireNonNull(transport, "transport");
        return this;
    }

    public CellBuilder clock(Clock clock) {
        this.clock = Objects.requireNonNull(clock, "clock");
        return this;
    }

    public CellBuilder scheduler(Scheduler scheduler) {
        this.scheduler = Objects.requireNonNull(scheduler, "scheduler");
        return this;
    }

    /** The policy repository: boot policies come from it, and the commander serves the team from it. */
    public CellBuilder repository(PolicyRepository repository) {
        this.repository = Objects.requireNonNull(repository, "repository");
        return this;
    }

    /**
     * Shares the parse of identical small policy units (the boot file, a role's files) with the
     * other cells of this process built with the same {@link ParsedUnits} (default: none): for
     * simulations of many cells in one process. The cell still runs every statement itself.
     */
    public CellBuilder parsedUnits(ParsedUnits shared) {
        this.parsedUnits = shared;
        return this;
    }

    /**
     * Shares the decodes of broadcast datagrams with the other cells of this process built with the
     * same {@link SharedDecodes} (default: none): for simulations of many cells in one process, where
     * every cell receives each discovery broadcast.
     */
    public CellBuilder sharedDecodes(SharedDecodes shared) {
        this.sharedDecodes = shared;
        return this;
    }

    /** Whether this vehicle is the acting commander from the start. */
    public CellBuilder commander(boolean commander) {
        this.commander = commander;
        return this;
    }

    /** Overrides the mission's {@code scheme} parameter (distributed by default). */
    public CellBuilder scheme(Scheme scheme) {
        this.scheme = Objects.requireNonNull(scheme, "scheme");
        return this;
    }

    /** Overrides the timing the mission's parameters give. */
    public CellBuilder timing(Timing timing) {
        this.timing = Objects.requireNonNull(timing, "timing");
        return this;
    }

    /** Seeds the cell's random choices (tick phase, retransmission jitter, the engine's random). */
    public CellBuilder seed(long seed) {
        this.seed = seed;
        return this;
    }

    /** Receives every decision of the team protocols. */
    public CellBuilder trace(Consumer<CellEvent> trace) {
        this.trace = Objects.requireNonNull(trace, "trace");
        return this;
    }

    /** Receives what policies print ({@code root print:}); discarded by default. */
    public CellBuilder output(Consumer<String> output) {
        this.output = Objects.requireNonNull(output, "output");
        return this;
    }

    /** Overrides the retransmission settings the timing gives ({@link Timing#senderSettings()}). */
    public CellBuilder senderSettings(SenderSettings settings) {
        this.senderSettings = Objects.requireNonNull(settings, "settings");
        return this;
    }

    /**
     * The vehicle's tasks: a role it is assigned starts those its mission requires (bound at
     * {@code root/task/<name>}), and withdrawing the role stops them. Default
     * {@link TaskProvider#NONE}: roles load without tasks.
     */
    public CellBuilder tasks(TaskProvider tasks) {
        this.tasks = Objects.requireNonNull(tasks, "tasks");
        return this;
    }

    /**
     * Whether the engine checks authorisation policies, and its default decision (default
     * {@link AuthMode#OFF}: nothing checked). With {@link AuthMode#DENY}, as deployed, a remote
     * role's event or invocation runs only when the receiving role's authorisations allow it.
     */
    public CellBuilder auth(AuthMode mode) {
        this.auth = Objects.requireNonNull(mode, "auth");
        return this;
    }

    public Cell build() {
        if (transport == null || clock == null || scheduler == null || repository == null) {
            throw new IllegalStateException("cell '" + vehicle + "' needs a transport, a clock, a scheduler and a"
                    + " policy repository");
        }
        return new Cell(this);
    }
}
