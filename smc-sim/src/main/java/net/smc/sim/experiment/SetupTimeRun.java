package net.smc.sim.experiment;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.Consumer;

import net.smc.core.cell.CellEvent;
import net.smc.core.cell.Scheme;
import net.smc.sim.team.TeamSimulation;
import net.smc.core.mission.Mission;
import net.smc.core.security.IdealAuthentication;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.InMemoryNetwork;
import net.smc.policy.api.PolicyRepository;

/**
 * One run of the set-up time experiment on the simulated network: a generated mission's whole team
 * (the commander and one vehicle per seat) starts at once on a {@link RadioNetwork}, with every
 * cell's CPU charged by {@link CpuCharge}; the set-up time is, as the paper's section V defines it,
 * from the commander's start (its {@code COMMANDING} event) until every role is started: each seat's
 * vehicle has had the assignment, fetched the role's policies from its manager, loaded them and
 * started the role ({@code ACCEPTED}, which a cell reports only after the role is loaded). Times are
 * simulated milliseconds; one seed replays the run exactly.
 *
 * <pre>{@code
 * SetupResult r = SetupTimeRun.run(generated, mission, Scheme.DISTRIBUTED, 1, seed, RadioNetwork.ADHOC_80211, costs, 120_000);
 * }</pre>
 */
public final class SetupTimeRun {
    private SetupTimeRun() {
    }

    /**
     * Runs one team until every role started or {@code limitMillis} of simulated time passed.
     *
     * @param mission the generated mission loaded for {@code scheme}
     */
    public static SetupResult run(GeneratedMission generated, Mission mission, Scheme scheme, int run, long seed,
                                  RadioNetwork radio, CpuCosts costs, long limitMillis) {
        return run(generated, mission, scheme, run, seed, radio, costs, limitMillis, report -> { });
    }

    /**
     * As {@link #run(GeneratedMission, Mission, Scheme, int, long, RadioNetwork, CpuCosts, long)}, and
     * hands {@code report} a diagnostic of the run: when the roles of each level of the tree
     * started, and where the charged CPU went and which kinds of message travelled ({@link CpuLedger#report}).
     */
    public static SetupResult run(GeneratedMission generated, Mission mission, Scheme scheme, int run, long seed,
                                  RadioNetwork radio, CpuCosts costs, long limitMillis, Consumer<String> report) {
        return run(generated, mission, scheme, run, seed, radio, costs, limitMillis, 0, report);
    }

    /**
     * As {@link #run(GeneratedMission, Mission, Scheme, int, long, RadioNetwork, CpuCosts, long, Consumer)},
     * with a team of {@code sparePercent} percent more vehicles than seats ({@link GeneratedMission#vehicles(int)}).
     */
    public static SetupResult run(GeneratedMission generated, Mission mission, Scheme scheme, int run, long seed,
                                  RadioNetwork radio, CpuCosts costs, long limitMillis, int sparePercent,
                                  Consumer<String> report) {
        Objects.requireNonNull(scheme, "scheme");
        if (limitMillis <= 0) {
            throw new IllegalArgumentException("time limit " + limitMillis + " ms must be above 0");
        }
        Progress progress = new Progress(generated.seats() - 1, generated.byName());
        TeamSimulation sim = TeamSimulation.builder(mission, new PolicyRepository(generated.repository()), seed)
                .vehicles(generated.vehicles(sparePercent)).scheme(scheme).link(radio.link()).listener(progress).build();
        // The team simulation seals every datagram (IdealAuthentication): the message follows the seal's counter.
        // A cell drops a discovery it would not answer before checking it: that costs no verification.
        // A manager holds discovery replies unchecked and checks those of the vehicles it tries to seat.
        IdealAuthentication auth = sim.idealAuthentication();
        CpuCharge charge = new CpuCharge(costs, mission.instanceName(), v -> generated.newUavPolicies(v, scheme), generated::loadsPolicy,
                IdealAuthentication.PAYLOAD_OFFSET, auth::dropsUnverified, auth::holdsUnverified);
        auth.onHeldChecked(charge::heldChecked);
        sim.vehicles().forEach(v -> charge.name(sim.address(v.id()), v.id()));
        InMemoryNetwork network = sim.network();
        network.setCpuModel(charge);
        network.setBandwidth(radio.bytesPerSecond());
        sim.start();
        sim.runUntil(progress::complete, limitMillis);
        long busiest = 0;
        for (Address a : network.attached()) {
            busiest = Math.max(busiest, network.cpuMicros(a));
        }
        report.accept(progress.levels() + progress.tail() + progress.assignments() + charge.ledger().report() + retransmissions(sim));
        double setup = progress.complete() && progress.start >= 0 ? progress.end - progress.start : -1;
        return new SetupResult(generated.seats(), scheme, "sim", run, setup, charge.datagrams(), charge.bytes(),
                busiest / 1_000.0, progress.seats.size(), undelivered(sim));
    }

    /** The critical messages the team's cells gave up on. */
    static long undelivered(TeamSimulation sim) {
        long failed = 0;
        for (net.smc.core.cell.Cell c : sim.cells()) {
            failed += c.communication().sender().counters().failed();
        }
        return failed;
    }

    /**
     * A line on the team's critical messages: sent, retransmitted, tail probes, given up on, and copies their receivers already
     * had (a retransmission whose first copy arrived: its Ack was lost, or it went too soon).
     */
    static String retransmissions(TeamSimulation sim) {
        long sent = 0;
        long retransmitted = 0;
        long fast = 0;
        long probes = 0;
        long duplicates = 0;
        for (net.smc.core.cell.Cell c : sim.cells()) {
            net.smc.core.comm.SenderCounters k = c.communication().sender().counters();
            sent += k.sent();
            retransmitted += k.retransmitted();
            fast += k.fastRetransmitted();
            probes += k.probes();
            duplicates += k.duplicates();
        }
        return "team's critical messages: " + sent + " sent, " + retransmitted + " retransmitted (" + fast
                + " before their timeout), " + probes + " tail probes, " + undelivered(sim) + " given up on, " + duplicates
                + " copies received again\n";
    }

    /** Follows the cells' events: the commander's start, and each seat's first acceptance (by level of the tree). */
    private static final class Progress implements Consumer<CellEvent> {
        final Set<String> seats = new HashSet<>();
        final int needed;
        final Map<String, RoleType> roles;
        /** Per level: when each of its seats was first accepted, in order. */
        final TreeMap<Integer, List<Long>> levels = new TreeMap<>();
        long start = -1;
        long end = -1;
        /** Per seat: when its manager first and last sent an assignment for it, and how many it sent. */
        final Map<String, long[]> tries = new HashMap<>();
        /** Per seat: who manages it; per vehicle: when it first started a role. */
        final Map<String, String> managerOf = new HashMap<>();
        final Map<String, Long> vehicleStarted = new HashMap<>();
        /** Per seat, when it was first accepted. */
        final Map<String, Long> seatStarted = new HashMap<>();
        /** Role assignments sent, and those that failed by why (vehicle names left out). */
        int assignments;
        final TreeMap<String, Integer> failures = new TreeMap<>();

        Progress(int needed, Map<String, RoleType> roles) {
            this.needed = needed;
            this.roles = roles;
        }

        @Override
        public void accept(CellEvent e) {
            if (e.kind() == CellEvent.Kind.COMMANDING && e.vehicle().equals(GeneratedMission.COMMANDER) && start < 0) {
                start = e.timeMillis();
            } else if (e.kind() == CellEvent.Kind.ASSIGNING) {
                assignments++;
                String seat = e.detail().substring(0, Math.max(0, e.detail().indexOf(' ')));
                long[] t = tries.computeIfAbsent(seat, k -> new long[] {e.timeMillis(), e.timeMillis(), 0});
                t[1] = e.timeMillis();
                t[2]++;
                managerOf.put(seat, e.vehicle());
            } else if (e.kind() == CellEvent.Kind.ASSIGNMENT_FAILED) {
                int colon = e.detail().indexOf(": ");
                String why = colon < 0 ? e.detail() : e.detail().substring(colon + 2);
                failures.merge(why.replaceAll("'[^']*'", "'…'"), 1, Integer::sum);
            } else if (e.kind() == CellEvent.Kind.ACCEPTED) {
                int space = e.detail().indexOf(' ');
                String seat = space < 0 ? e.detail() : e.detail().substring(0, space);
                if (seats.add(seat)) {
                    level(seat, e.timeMillis());
                    seatStarted.put(seat, e.timeMillis());
                    vehicleStarted.putIfAbsent(e.vehicle(), e.timeMillis());
                    if (seats.size() == needed) {
                        end = e.timeMillis();
                    }
                }
            }
        }

        private void level(String seat, long at) {
            int level = level(seat);
            if (level >= 0) {
                levels.computeIfAbsent(level, l -> new ArrayList<>()).add(at);
            }
        }

        /** One line: the role assignments sent for the seats, and those that failed, by why. */
        String assignments() {
            StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "role assignments %d for %d seats", assignments, needed));
            int failed = failures.values().stream().mapToInt(Integer::intValue).sum();
            if (failed > 0) {
                s.append(String.format(Locale.ROOT, "; %d failed:", failed));
                failures.entrySet().stream().sorted(Map.Entry.<String, Integer>comparingByValue().reversed())
                        .forEach(f -> s.append(String.format(Locale.ROOT, " %d %s;", f.getValue(), f.getKey())));
                s.setLength(s.length() - 1);
            }
            return s.append('\n').toString();
        }

        boolean complete() {
            return seats.size() >= needed;
        }

        /**
         * One line: per level of the tree, when its first role started, when half and nine in ten of its
         * roles had (nearest rank), and when its last did, ms after the commander's start.
         */
        String levels() {
            StringBuilder s = new StringBuilder("roles started, ms after the commander's start, by level (first/half/90%/last):");
            levels.forEach((level, times) -> s.append(String.format(Locale.ROOT, " L%d %d/%d/%d/%d", level,
                    times.get(0) - start, rank(times, 0.5) - start, rank(times, 0.9) - start,
                    times.get(times.size() - 1) - start)));
            return s.append('\n').toString();
        }

        /**
         * One line on the slowest tenth of the deepest level's roles, where their time went, on average:
         * until their manager started, from then until its first assignment for the seat (discovery,
         * choosing, the manager's own queue), over further assignments when the first failed, and from
         * the last assignment until the role started (delivery, policies, loading).
         */
        String tail() {
            if (levels.isEmpty() || start < 0) {
                return "";
            }
            int deepest = levels.lastKey();
            List<Map.Entry<String, Long>> leaves = seatStarted.entrySet().stream()
                    .filter(en -> level(en.getKey()) == deepest)
                    .sorted(Map.Entry.comparingByValue()).toList();
            List<Map.Entry<String, Long>> slow = leaves.subList(leaves.size() - Math.max(1, leaves.size() / 10), leaves.size());
            double manager = 0;
            double first = 0;
            double retry = 0;
            double deliver = 0;
            double count = 0;
            int n = 0;
            for (Map.Entry<String, Long> en : slow) {
                long[] t = tries.get(en.getKey());
                Long parent = vehicleStarted.get(managerOf.get(en.getKey()));
                if (t == null) {
                    continue;
                }
                long up = parent == null ? start : parent;
                manager += up - start;
                first += t[0] - up;
                retry += t[1] - t[0];
                deliver += en.getValue() - t[1];
                count += t[2];
                n++;
            }
            if (n == 0) {
                return "";
            }
            return String.format(Locale.ROOT, "slowest %d of L%d, on average: manager started %.0f ms, first assignment "
                    + "%.0f ms later, last %.0f ms after the first (%.2f assignments a seat), role started %.0f ms after "
                    + "the last\n", n, deepest, manager / n, first / n, retry / n, count / n, deliver / n)
                    + latest(leaves.subList(Math.max(0, leaves.size() - 3), leaves.size()));
        }

        /**
         * One line on each of {@code last} (the deepest level's last seats to start, in start order), the
         * latest first: when it started, and when its manager started and sent it its first and last
         * assignment, ms after the commander's start (the tail of one run: which seat waited, and on what).
         */
        private String latest(List<Map.Entry<String, Long>> last) {
            StringBuilder s = new StringBuilder();
            for (int i = last.size() - 1; i >= 0; i--) {
                Map.Entry<String, Long> en = last.get(i);
                long[] t = tries.get(en.getKey());
                if (t == null) {
                    continue;
                }
                String manager = managerOf.get(en.getKey());
                Long parent = vehicleStarted.get(manager);
                s.append(String.format(Locale.ROOT, "  %s started at %d: its manager %s at %d, first assignment at %d, "
                        + "last at %d (%d sent)\n", en.getKey(), en.getValue() - start, manager,
                        (parent == null ? start : parent) - start, t[0] - start, t[1] - start, t[2]));
            }
            return s.toString();
        }

        /** The tree level of {@code seat}'s role, or -1 for a seat of no generated role. */
        private int level(String seat) {
            int hash = seat.indexOf('#');
            RoleType role = roles.get(hash < 0 ? seat : seat.substring(0, hash));
            return role == null ? -1 : role.level();
        }

        /** The nearest-rank quantile {@code q} of times already in order. */
        private static long rank(List<Long> times, double q) {
            return times.get(Math.max(0, (int) Math.ceil(q * times.size()) - 1));
        }
    }
}
