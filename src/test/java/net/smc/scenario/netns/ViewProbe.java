package net.smc.scenario.netns;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

import net.smc.core.transport.Address;
import net.smc.core.transport.udp.StatusClient;

/**
 * The eyes of a multi-process test: a program run on a host of the lab (the test's own JVM is
 * outside the lab's namespaces and cannot reach the nodes) that asks every node for its status view
 * ({@link StatusClient}, what {@code smc status} does), all at once, every {@code INTERVAL_MS}, and
 * replaces {@code FILE} with the latest round each time, atomically, so the test always reads one
 * whole round:
 *
 * <pre>
 * round N EPOCH_MS          when the round started
 * ADDR:PORT {"vehicle":...}  a node's view
 * ADDR:PORT -                no answer within the query's timeout
 * </pre>
 *
 * {@code java -cp CLASSPATH net.smc.scenario.netns.ViewProbe FILE INTERVAL_MS ADDR:PORT...}; it prints
 * {@code probing N nodes} once, then runs until killed.
 */
final class ViewProbe {
    /** Per query, split by the client into three tries: a lost query or reply costs a third of it. */
    static final Duration QUERY_TIMEOUT = Duration.ofMillis(600);

    private ViewProbe() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 3) {
            System.err.println("usage: ViewProbe FILE INTERVAL_MS ADDR:PORT...");
            System.exit(2);
        }
        Path file = Path.of(args[0]);
        long interval = Long.parseLong(args[1]);
        List<Address> nodes = new ArrayList<>();
        for (int i = 2; i < args.length; i++) {
            nodes.add(Address.parse(args[i]));
        }
        ExecutorService pool = Executors.newFixedThreadPool(nodes.size());
        System.out.println("probing " + nodes.size() + " nodes");
        System.out.flush();
        for (long round = 1; ; round++) {
            long start = System.currentTimeMillis();
            List<Future<String>> answers = new ArrayList<>();
            for (Address node : nodes) {
                answers.add(pool.submit(() -> query(node.toInetSocketAddress())));
            }
            StringBuilder text = new StringBuilder("round " + round + " " + start + "\n");
            for (int i = 0; i < nodes.size(); i++) {
                text.append(nodes.get(i)).append(' ').append(answers.get(i).get()).append('\n');
            }
            Path next = file.resolveSibling(file.getFileName() + ".next");
            Files.writeString(next, text, StandardCharsets.UTF_8);
            Files.move(next, file, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            Thread.sleep(Math.max(0, start + interval - System.currentTimeMillis()));
        }
    }

    private static String query(InetSocketAddress node) {
        try {
            return StatusClient.query(node, QUERY_TIMEOUT);
        } catch (IOException e) {
            return "-";
        }
    }
}
