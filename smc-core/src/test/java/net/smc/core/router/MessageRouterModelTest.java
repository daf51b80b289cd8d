package net.smc.core.router;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import net.smc.core.message.Ack;
import net.smc.core.message.Envelope;
import net.smc.core.message.Heartbeat;
import net.smc.core.message.Leave;
import net.smc.core.message.Message;
import net.smc.core.message.MessageType;
import org.junit.jupiter.api.Test;

/**
 * The router against a model that is obviously right and slow: each role's operations kept as a
 * list of rules, the last rule matching a packet deciding whether the role receives it. Random
 * sequences of registrations, de-registrations, removals and dispatches from seeded generators
 * must give the same deliveries, each role at most once per packet.
 */
class MessageRouterModelTest {
    private static final MessageType[] TYPES = {MessageType.HEARTBEAT, MessageType.ACK, MessageType.LEAVE};
    private static final String[] SOURCES = {"uav1", "uav2", "uav3", "uav4"};
    /** Packets come from the registered sources and from one nobody registers. */
    private static final String[] SENDERS = {"uav1", "uav2", "uav3", "uav4", "stranger"};

    /** One operation; {@code type} or {@code source} null means any. */
    private record Rule(Recorder role, MessageType type, String source, boolean include) {
        boolean matches(MessageType t, String s) {
            return (type == null || type == t) && (source == null || source.equals(s));
        }
    }

    private static final class Model {
        final List<Rule> rules = new ArrayList<>();

        boolean receives(Recorder role, MessageType t, String s) {
            boolean in = false;
            for (Rule r : rules) {
                if (r.role == role && r.matches(t, s)) {
                    in = r.include;
                }
            }
            return in;
        }
    }

    @Test
    void randomSequences_deliverAsTheModelSays() {
        for (long seed = 0; seed < 3_000; seed++) {
            runSequence(seed, 150);
        }
    }

    private static void runSequence(long seed, int steps) {
        Random random = new Random(seed);
        MessageRouter router = new MessageRouter();
        Model model = new Model();
        List<Recorder> roles = new ArrayList<>();
        for (int i = 0; i < 2 + random.nextInt(5); i++) {
            roles.add(new Recorder("role" + i));
        }
        List<String> log = new ArrayList<>();
        for (int step = 0; step < steps; step++) {
            Recorder role = roles.get(random.nextInt(roles.size()));
            MessageType type = TYPES[random.nextInt(TYPES.length)];
            String source = SOURCES[random.nextInt(SOURCES.length)];
            int op = random.nextInt(10);
            boolean include = op < 4;
            switch (op) {
                case 0, 4 -> {
                    if (include) {
                        router.register(role, type);
                    } else {
                        router.deregister(role, type);
                    }
                    model.rules.add(new Rule(role, type, null, include));
                    log.add((include ? "register " : "deregister ") + role + " " + type);
                }
                case 1, 5 -> {
                    if (include) {
                        router.register(role, source);
                    } else {
                        router.deregister(role, source);
                    }
                    model.rules.add(new Rule(role, null, source, include));
                    log.add((include ? "register " : "deregister ") + role + " " + source);
                }
                case 2, 3, 6, 7 -> {
                    if (include) {
                        router.register(role, type, source);
                    } else {
                        router.deregister(role, type, source);
                    }
                    model.rules.add(new Rule(role, type, source, include));
                    log.add((include ? "register " : "deregister ") + role + " " + type + " " + source);
                }
                case 8 -> {
                    router.deregisterAll(role);
                    model.rules.removeIf(r -> r.role == role);
                    log.add("deregisterAll " + role);
                }
                default -> {
                    for (int k = 0; k < 4; k++) {
                        dispatchAndCompare(seed, log, router, model, roles,
                                TYPES[random.nextInt(TYPES.length)], SENDERS[random.nextInt(SENDERS.length)]);
                    }
                }
            }
        }
        for (MessageType t : TYPES) {
            for (String s : SENDERS) {
                dispatchAndCompare(seed, log, router, model, roles, t, s);
            }
        }
        for (Recorder role : roles) {
            router.deregisterAll(role);
        }
        assertEquals(0, router.sourceRows(), "seed " + seed + ": source rows left after every role was removed");
    }

    private static void dispatchAndCompare(long seed, List<String> log, MessageRouter router, Model model,
            List<Recorder> roles, MessageType type, String sender) {
        roles.forEach(r -> r.received.clear());
        Envelope e = new Envelope(sender, 1, packet(type));
        int n = router.dispatch(e);
        Set<Recorder> expected = new LinkedHashSet<>();
        for (Recorder role : roles) {
            if (model.receives(role, type, sender)) {
                expected.add(role);
            }
            if (role.received.size() > 1) {
                fail("seed " + seed + ": " + role + " received " + type + " from " + sender + " "
                        + role.received.size() + " times after " + log);
            }
            if (router.receives(role, type, sender) != model.receives(role, type, sender)) {
                fail("seed " + seed + ": receives(" + role + ", " + type + ", " + sender + ") disagrees after " + log);
            }
        }
        Set<Recorder> actual = new LinkedHashSet<>();
        roles.stream().filter(r -> !r.received.isEmpty()).forEach(actual::add);
        if (!expected.equals(actual) || n != expected.size()) {
            fail("seed " + seed + ": " + type + " from " + sender + " reached " + actual + " (" + n
                    + " deliveries); the model says " + expected + " after " + log);
        }
    }

    private static Message packet(MessageType type) {
        return switch (type) {
            case HEARTBEAT -> new Heartbeat("r", 1, 0);
            case ACK -> new Ack(1);
            default -> new Leave("");
        };
    }
}
