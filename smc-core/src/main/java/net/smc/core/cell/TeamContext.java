package net.smc.core.cell;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.Consumer;

import net.smc.core.capability.CapabilityDescription;
import net.smc.core.comm.CommunicationManager;
import net.smc.core.comm.DeliveryListener;
import net.smc.core.comm.FailureReason;
import net.smc.core.message.Envelope;
import net.smc.core.message.Identity;
import net.smc.core.message.Message;
import net.smc.core.message.PolicyRef;
import net.smc.core.message.RoleAssignment;
import net.smc.core.mission.MissionRole;
import net.smc.core.transport.Address;
import net.smc.core.transport.Clock;
import net.smc.core.transport.Scheduler;
import net.smc.policy.api.PolicyRepository;

/**
 * What every part of the team protocols shares and never changes: the cell's identity (vehicle and
 * mission), the mission's seats ({@link Slots}) and times ({@link Timing}), the injected clock,
 * scheduler and Communication-Manager, the vehicle's capability description, its policy files, the
 * host cell, and where decisions are traced. Made once per cell by {@link #builder()}; the helpers
 * below are the protocols' common vocabulary (send, emit, reject, identities, policy files).
 */
record TeamContext(String self, String missionId, Slots slots, Timing timing, long pendingMillis,
                   CommunicationManager comm, Clock clock, Scheduler scheduler, CapabilityDescription description,
                   PolicyStore store, PolicyRepository repository, TeamProtocol.Host host, Consumer<CellEvent> trace,
                   Map<String, Long> rejected) {

    static Builder builder() {
        return new Builder();
    }

    /** Collects the context; every part is required except the repository. */
    static final class Builder {
        private String self;
        private Slots slots;
        private Timing timing;
        private CommunicationManager comm;
        private Clock clock;
        private Scheduler scheduler;
        private CapabilityDescription description;
        private PolicyStore store;
        private PolicyRepository repository;
        private TeamProtocol.Host host;
        private Consumer<CellEvent> trace;

        Builder self(String vehicle) {
            this.self = vehicle;
            return this;
        }

        Builder slots(Slots s) {
            this.slots = s;
            return this;
        }

        Builder timing(Timing t) {
            this.timing = t;
            return this;
        }

        Builder comm(CommunicationManager c) {
            this.comm = c;
            return this;
        }

        Builder clock(Clock c) {
            this.clock = c;
            return this;
        }

        Builder scheduler(Scheduler s) {
            this.scheduler = s;
            return this;
        }

        Builder description(CapabilityDescription d) {
            this.description = d;
            return this;
        }

        Builder store(PolicyStore s) {
            this.store = s;
            return this;
        }

        /** The local policy repository, or null when the cell has none. */
        Builder repository(PolicyRepository r) {
            this.repository = r;
            return this;
        }

        Builder host(TeamProtocol.Host h) {
            this.host = h;
            return this;
        }

        Builder trace(Consumer<CellEvent> t) {
            this.trace = t;
            return this;
        }

        TeamContext build() {
            return new TeamContext(Objects.requireNonNull(self, "self"), slots.mission().instanceName(),
                    Objects.requireNonNull(slots, "slots"), Objects.requireNonNull(timing, "timing"),
                    timing.pendingMillis(), Objects.requireNonNull(comm, "comm"), Objects.requireNonNull(clock, "clock"),
                    Objects.requireNonNull(scheduler, "scheduler"), Objects.requireNonNull(description, "description"),
                    Objects.requireNonNull(store, "store"), repository, Objects.requireNonNull(host, "host"),
                    Objects.requireNonNull(trace, "trace"), new TreeMap<>());
        }
    }

    Optional<Address> address(String vehicle) {
        return comm.addressOf(vehicle);
    }

    void send(Address to, Message m) {
        comm.send(to, m);
    }

    /** Connectionless, starting no session: a discovery reply ({@code CommunicationManager.sendWithoutHandshake}). */
    void sendWithoutHandshake(Address to, Message m) {
        comm.sendWithoutHandshake(to, m);
    }

    void reject(Envelope env, String why) {
        rejected.merge(env.type().name(), 1L, Long::sum);
        emit(CellEvent.Kind.REJECTED, env.type() + " from " + env.sender() + ": " + why);
    }

    void emit(CellEvent.Kind kind, String detail) {
        trace.accept(new CellEvent(clock.nowMillis(), self, kind, detail));
    }

    Identity identityOf(Seat seat) {
        return new Identity(missionId, slots.level(seat.role()), slots.sequence(seat));
    }

    boolean canAlsoHold(List<Seat> held, Seat seat) {
        if (held.stream().anyMatch(s -> s.role().equals(seat.role()))) {
            return false;
        }
        List<String> names = new ArrayList<>();
        held.forEach(s -> names.add(s.role()));
        names.add(seat.role());
        return slots.mission().allowsOnOneVehicle(names);
    }

    boolean policiesHeld(String role) {
        MissionRole r = slots.role(role);
        return r.policies().stream().allMatch(u -> store.get(u, PolicyStore.ANY_VERSION).isPresent())
                && r.authorisations().stream().allMatch(u -> store.get(u, PolicyStore.ANY_VERSION).isPresent());
    }

    /** The policy files of {@code role} itself: its role-missions and authorisations. */
    Set<String> ownPolicyUris(String role) {
        MissionRole r = slots.role(role);
        Set<String> own = new LinkedHashSet<>(r.policies());
        own.addAll(r.authorisations());
        return own;
    }

    /**
     * The policy files a manager sends a vehicle right behind its assignment to {@code role}
     * (Recruiter): the role's own, then those of the roles it manages directly, which the vehicle
     * will send its own children. The files of the roles further down it fetches itself.
     */
    Set<String> policiesWithAssignment(String role) {
        Set<String> files = ownPolicyUris(role);
        for (String managed : slots.managedRoles(role)) {
            files.addAll(ownPolicyUris(managed));
        }
        return files;
    }

    /** The policy URIs of a role and of every role it manages, down the tree. */
    List<String> subtreePolicyUris(String role) {
        Set<String> uris = new LinkedHashSet<>();
        List<String> pending = new ArrayList<>(List.of(role));
        while (!pending.isEmpty()) {
            MissionRole r = slots.role(pending.remove(0));
            uris.addAll(r.policies());
            uris.addAll(r.authorisations());
            pending.addAll(slots.managedRoles(r.name()));
        }
        return List.copyOf(uris);
    }

    /** The policies of a role and of every role below it, as this cell holds them. */
    List<PolicyRef> policyRefs(String role) {
        List<PolicyRef> refs = new ArrayList<>();
        for (String uri : subtreePolicyUris(role)) {
            store.ref(uri).ifPresent(refs::add);
        }
        return refs;
    }

    List<String> allPolicyUris() {
        Set<String> uris = new LinkedHashSet<>();
        for (MissionRole r : slots.mission().roles()) {
            uris.addAll(r.policies());
            uris.addAll(r.authorisations());
        }
        return List.copyOf(uris);
    }

    /** The repository holder's fallback: a file of the local repository, if the cell has one. */
    Optional<PolicyStore.Entry> fromRepository(String uri) {
        if (repository == null) {
            return Optional.empty();
        }
        try {
            return Optional.of(store.load(repository, uri));
        } catch (IllegalArgumentException missing) {
            return Optional.empty();
        }
    }

    /** A parent followed by its own ancestors, cut to the most a message carries. */
    static List<String> lineage(String parentVehicle, List<String> above) {
        List<String> chain = new ArrayList<>();
        chain.add(parentVehicle);
        for (String a : above) {
            if (chain.size() == RoleAssignment.MAX_ANCESTORS) {
                break;
            }
            chain.add(a);
        }
        return List.copyOf(chain);
    }

    static String truncate(String s) {
        return s.length() <= 255 ? s : s.substring(0, 252) + "...";
    }

    static DeliveryListener failureOnly(Runnable onFailure) {
        Objects.requireNonNull(onFailure);
        return new DeliveryListener() {
            @Override
            public void failed(long id, FailureReason reason) {
                onFailure.run();
            }
        };
    }
}
