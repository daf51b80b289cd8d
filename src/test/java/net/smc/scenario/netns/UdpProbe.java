package net.smc.scenario.netns;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URISyntaxException;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A tiny UDP program the lab's tests run inside a host's namespace (JDK only, so it runs wherever
 * the tests do): {@code java -cp CLASSES net.smc.scenario.netns.UdpProbe ...}.
 *
 * <ul>
 *   <li>{@code listen PORT SECONDS}: binds {@code 0.0.0.0:PORT}, prints {@code listening on PORT}, then
 *       for each datagram {@code from HOST:PORT TEXT}; except that datagrams reading {@code data} are
 *       only counted, and a datagram {@code end ROUND} prints {@code end ROUND: N data} and restarts
 *       the count. Exits after SECONDS.</li>
 *   <li>{@code send HOST PORT TEXT COUNT}: sends TEXT COUNT times (broadcast allowed), pausing 1 ms
 *       after every {@value #BURST} datagrams so a receiver's socket buffer never overflows.</li>
 * </ul>
 */
final class UdpProbe {
    static final int BURST = 25;

    private UdpProbe() {
    }

    public static void main(String[] args) throws Exception {
        switch (args.length > 0 ? args[0] : "") {
            case "listen" -> listen(Integer.parseInt(args[1]), Integer.parseInt(args[2]));
            case "send" -> send(args[1], Integer.parseInt(args[2]), args[3], Integer.parseInt(args[4]));
            default -> {
                System.err.println("usage: UdpProbe listen PORT SECONDS | send HOST PORT TEXT COUNT");
                System.exit(2);
            }
        }
    }

    /** The command that runs this program with {@code args}, on the JVM and classes of the caller. */
    static List<String> command(String... args) {
        Path classes;
        try {
            classes = Path.of(UdpProbe.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException("cannot locate the classes of " + UdpProbe.class.getName(), e);
        }
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-Xshare:auto",
                "-cp", classes.toString(), UdpProbe.class.getName()));
        command.addAll(List.of(args));
        return command;
    }

    private static void listen(int port, int seconds) throws IOException {
        long deadline = System.nanoTime() + seconds * 1_000_000_000L;
        try (DatagramSocket socket = new DatagramSocket(new InetSocketAddress("0.0.0.0", port))) {
            System.out.println("listening on " + port);
            System.out.flush();
            byte[] buffer = new byte[2_048];
            int data = 0;
            while (true) {
                long leftMillis = (deadline - System.nanoTime()) / 1_000_000;
                if (leftMillis < 1) {
                    return;
                }
                socket.setSoTimeout((int) leftMillis);
                DatagramPacket packet = new DatagramPacket(buffer, buffer.length);
                try {
                    socket.receive(packet);
                } catch (SocketTimeoutException e) {
                    return;
                }
                String text = new String(packet.getData(), 0, packet.getLength(), StandardCharsets.UTF_8);
                if (text.equals("data")) {
                    data++;
                } else if (text.startsWith("end ")) {
                    System.out.println(text + ": " + data + " data");
                    data = 0;
                } else {
                    System.out.println("from " + packet.getAddress().getHostAddress() + ":" + packet.getPort() + " " + text);
                }
                System.out.flush();
            }
        }
    }

    private static void send(String host, int port, String text, int count) throws IOException, InterruptedException {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        InetSocketAddress target = new InetSocketAddress(InetAddress.getByName(host), port);
        try (DatagramSocket socket = new DatagramSocket()) {
            socket.setBroadcast(true);
            for (int i = 1; i <= count; i++) {
                socket.send(new DatagramPacket(bytes, bytes.length, target));
                if (i % BURST == 0) {
                    Thread.sleep(1);
                }
            }
        }
    }
}
