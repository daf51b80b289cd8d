package net.smc.sim.experiment;

import java.util.BitSet;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.function.BiPredicate;
import java.util.function.ToIntFunction;

import net.smc.core.message.MessageType;
import net.smc.core.message.WireFormat;
import net.smc.core.security.IdealAuthentication;
import net.smc.core.security.WireSizes;
import net.smc.core.transport.Address;
import net.smc.core.transport.sim.CpuModel;
import net.smc.sim.experiment.CpuLedger.Category;

/**
 * The CPU a cell spends per datagram, from measured per-operation {@link CpuCosts}, for the
 * protection real traffic gets ({@code net.smc.core.security}), although the simulation itself uses
 * ideal authentication for speed:
 * <ul>
 *   <li>every datagram sent or received is encoded or decoded (fixed + per byte);</li>
 *   <li>a broadcast is signed (Ed25519) by its sender and verified by each receiver; a unicast is
 *       MAC'd (HMAC-SHA256) by both ends once its sender has a session with its receiver, and
 *       signed and verified before; the first signed datagram a cell takes from another costs it
 *       the verification of that vehicle's credential too;</li>
 *   <li>the first unicast between two cells (other than a discovery reply or its withdrawal) starts
 *       the handshake that sets their session up ({@code SecureTransport}, the security design
 *       note's "The handshake"): four signed HELLOs, the first sent with that unicast, each of the
 *       others when its sender takes the one before; the initiator has its session when it takes
 *       the second, the other side when it takes the third. Each HELLO costs its sender a signature
 *       and its receiver a verification; each side makes an X25519 key pair (when it sends or takes
 *       the first HELLO) and agrees keys once, together one {@code agreeNanos} (which
 *       {@link Calibration} times as both), half charged at each. A HELLO is not carried on
 *       the simulated network: it is taken to arrive with the next datagram its receiver takes from
 *       its sender (the acknowledgements that follow a first unicast at once), and its bytes go on
 *       its sender's radio with that sender's next datagram;</li>
 *   <li>a {@code PolicyReply} of a policy its receiver loads (given by {@code loads}: the files of
 *       the role it takes, not the copies a manager keeps to serve the roles below it or a backup
 *       commander keeps of the mission) costs the parsing and loading of the text it carries, per
 *       byte of text (of the whole message when fragmented, charged with its first fragment), once
 *       per file and version: the same file sent again (by another manager that offered the vehicle
 *       the same role, behind an assignment it refused) is stored, not loaded again;</li>
 *   <li>a {@code PolicyReply} whose text is {@link WireFormat#MIN_DEFLATED_POLICY_TEXT} bytes or
 *       more costs its sender the deflating of the text (the encoder deflates every such text and
 *       sends the deflated form when shorter), and one that came deflated costs its receiver the
 *       inflating, each per byte of text and charged with the message's first datagram. A lost
 *       datagram's retransmission is charged both again, as it is its codec, although the sender's
 *       transport resends the datagrams it encoded;</li>
 *   <li>a {@code DiscoveryReply} costs its receiver one condition per {@code newUAV} policy it runs
 *       (given by {@code newUavPolicies} from the receiving vehicle's id);</li>
 *   <li>a datagram its receiver drops before checking it, because the cell would ignore it whoever
 *       sent it (a discovery it would not answer: {@code AuthenticatingTransport.setUnverifiedFilter},
 *       given by {@code dropsUnverified}), costs its decoding only: no verification, and it is no
 *       contact;</li>
 *   <li>a discovery reply to a cell not met yet is signed and starts no handshake (the team
 *       protocols send it so: {@code AuthenticatingTransport.sendWithoutHandshake}); its receiver,
 *       which holds it unchecked to read it first (given by {@code holdsUnverified}), pays its
 *       decoding only, and no contact is made. When the receiver checks it later
 *       ({@link #heldChecked}) that check (the credential's verification and the signature's, or
 *       a MAC when the two have met) is charged with the receiver's next datagram; the first contact
 *       follows when one of the two sends the other something. A withdrawal of a discovery reply goes
 *       and is held the same way.</li>
 * </ul>
 * The radio carries each datagram as long as the real one would be ({@link #airBytes}: the payload
 * in its {@code SIGNED} or {@code PAIR_MAC} envelope, {@link WireSizes}), not the simulation's own
 * seal, and the HELLOs beside them. Vehicles are known by the sender field of the datagrams they
 * send. Also counts the datagrams and bytes sent as the real radio would (a broadcast once: one
 * radio transmission; the HELLOs too). Deterministic: no clock, no randomness.
 */
public final class CpuCharge implements CpuModel {
    /** Reads the message in a datagram as the network carries it (after the transport's seal, if any). */
    private final MessageHeaders headers;

    /** The seal round the payload on the simulated network, bytes: counter and tag, or none for bare messages. */
    private final int sealBytes;
    /** The mission the vehicles' credentials name (their length is in every signed datagram). */
    private final String mission;
    private final CpuCosts costs;
    private final ToIntFunction<String> newUavPolicies;
    private final BiPredicate<String, String> loads;
    private final BiPredicate<Address, byte[]> dropsUnverified;
    private final BiPredicate<Address, byte[]> holdsUnverified;
    /** What is known of each address that sent or received: its number, vehicle and the credentials it verified. */
    private final Map<Address, Node> nodes = new HashMap<>();
    private final CpuLedger ledger = new CpuLedger();
    /** The handshakes between pairs of cells, by the pair's key ({@link #handshake}). */
    private final Map<Long, Handshake> handshakes = new HashMap<>();
    /** The datagram {@link #sendMicros} was last asked about, and the bytes the radio sends for it. */
    private byte[] lastSent;
    private long lastAirBytes;
    private long datagrams;
    private long bytes;

    /**
     * @param newUavPolicies how many {@code newUAV} policies the vehicle with this id runs
     * @param loads          whether the vehicle with this id (first) loads the policy of this URI (second)
     * @param mission        the mission the vehicles' credentials name
     * @param payloadOffset  where the encoded message starts in a datagram as the network carries it:
     *                       {@code IdealAuthentication.PAYLOAD_OFFSET} on a team simulation's network
     *                       (its seal comes first, {@code IdealAuthentication.SEAL_BYTES} in all),
     *                       0 for bare messages
     */
    public CpuCharge(CpuCosts costs, String mission, ToIntFunction<String> newUavPolicies, BiPredicate<String, String> loads,
                     int payloadOffset) {
        this(costs, mission, newUavPolicies, loads, payloadOffset, (at, data) -> false, (at, data) -> false);
    }

    /** As the full constructor, with no cell holding datagrams unchecked. */
    public CpuCharge(CpuCosts costs, String mission, ToIntFunction<String> newUavPolicies, BiPredicate<String, String> loads,
                     int payloadOffset, BiPredicate<Address, byte[]> dropsUnverified) {
        this(costs, mission, newUavPolicies, loads, payloadOffset, dropsUnverified, (at, data) -> false);
    }

    /**
     * As {@link #CpuCharge(CpuCosts, ToIntFunction, BiPredicate, int)}, with the receivers' tests
     * of what they drop unchecked and what they hold unchecked.
     *
     * @param dropsUnverified whether the cell at this address drops this datagram (as the network
     *                        carries it) before checking it; asked when its CPU takes the datagram up
     * @param holdsUnverified whether the cell at this address holds this datagram unchecked, to read
     *                        it first ({@code IdealAuthentication.holdsUnverified}); asked likewise
     */
    public CpuCharge(CpuCosts costs, String mission, ToIntFunction<String> newUavPolicies, BiPredicate<String, String> loads,
                     int payloadOffset, BiPredicate<Address, byte[]> dropsUnverified,
                     BiPredicate<Address, byte[]> holdsUnverified) {
        this.mission = Objects.requireNonNull(mission, "mission");
        this.dropsUnverified = Objects.requireNonNull(dropsUnverified, "dropsUnverified");
        this.holdsUnverified = Objects.requireNonNull(holdsUnverified, "holdsUnverified");
        if (payloadOffset < 0) {
            throw new IllegalArgumentException("payload offset " + payloadOffset + " must be 0 or more");
        }
        this.headers = new MessageHeaders(payloadOffset);
        this.sealBytes = payloadOffset == 0 ? 0 : IdealAuthentication.SEAL_BYTES;
        this.costs = Objects.requireNonNull(costs, "costs");
        this.newUavPolicies = Objects.requireNonNull(newUavPolicies, "newUavPolicies");
        this.loads = Objects.requireNonNull(loads, "loads");
    }

    @Override
    public long sendMicros(Address at, Address to, byte[] data) {
        Node node = node(at);
        if (node.vehicle == null) {
            String named = headers.sender(data);   // "" while it sends only what leaves its sender to the transport
            if (!named.isEmpty()) {
                node.vehicle = named;
                ledger.name(node.number, named);
            }
        }
        int type = type(data);
        int payload = Math.max(0, data.length - sealBytes);
        double ns = owed(node) + charge(node, Category.CODEC, codec(data.length));
        if (type == MessageType.POLICY_REPLY.code()) {
            MessageHeaders.PolicyText text = headers.policyText(data);
            if (text != null && text.bytes() >= WireFormat.MIN_DEFLATED_POLICY_TEXT) {
                ns += charge(node, Category.DEFLATE, costs.deflateNanosPerByte() * text.bytes());
            }
        }
        long message;
        long hellos = node.owedAirBytes;   // sent since this node's last datagram; counted then (hello)
        node.owedAirBytes = 0;
        Node peer = to == null ? null : node(to);
        Handshake h = peer == null ? null : handshake(node, peer);
        if (h != null && h.hasSession(node)) {
            message = WireSizes.pairMac(node.vehicle == null ? "" : node.vehicle, payload);
            ns += charge(node, Category.MAC, mac(data.length));
        } else {
            message = WireSizes.signed(node.vehicle == null ? "" : node.vehicle, mission, payload);
            ns += charge(node, Category.SIGN, costs.signNanos());
            if (h != null && h.steps == 0 && type != MessageType.DISCOVERY_REPLY.code()
                    && type != MessageType.WITHDRAWAL.code()) {
                // The first unicast that is not a discovery reply or its withdrawal starts the handshake.
                h.initiator = node.number;
                h.steps = 1;
                hellos += hello(node, peer);
                ns += charge(node, Category.HANDSHAKE, costs.signNanos() + costs.agreeNanos() / 2);   // HELLO 1, a key pair
            }
        }
        datagrams++;
        bytes += message;
        ledger.sent(type, message);
        lastSent = data;
        lastAirBytes = message + hellos;
        return micros(ns);
    }

    /**
     * The bytes the real radio sends for {@code data}, the datagram {@link #sendMicros} was just asked
     * about: the payload in the envelope its sender's security layer gives it ({@code SIGNED} with the
     * credential, or {@code PAIR_MAC} under a session), and the HELLOs its sender sent since its last
     * datagram or with this one; the simulation's seal is not sent.
     */
    @Override
    public long airBytes(Address at, Address to, byte[] data) {
        return data == lastSent ? lastAirBytes : data.length;
    }

    @Override
    public long receiveMicros(Address at, Address from, byte[] data, boolean broadcast) {
        Node node = node(at);
        if (dropsUnverified.test(at, data)) {
            ledger.droppedUnverified(node.number, type(data));
            return micros(owed(node) + charge(node, Category.CODEC, codec(data.length)));
        }
        if (holdsUnverified.test(at, data)) {
            ledger.heldUnverified(node.number, type(data));
            return micros(owed(node) + charge(node, Category.CODEC, codec(data.length)));
        }
        Node sender = node(from);
        double ns = owed(node) + charge(node, Category.CODEC, codec(data.length));
        Handshake h = broadcast ? null : handshake(node, sender);
        if (h != null && h.hasSession(sender)) {
            ns += charge(node, Category.MAC, mac(data.length));
        } else {
            ns += charge(node, Category.VERIFY, costs.verifyNanos());
            ns += credential(node, sender);
        }
        if (h != null) {
            ns += takeHello(node, sender, h);
        }
        int type = type(data);
        ledger.received(node.number, type);
        if (type == MessageType.POLICY_REPLY.code()) {
            MessageHeaders.PolicyText text = headers.policyText(data);
            // A second copy (a retransmission whose first copy arrived) is dropped by the duplicate
            // window once decoded: its text is neither inflated nor loaded again.
            if (text != null && node.firstCopy(from, headers.messageId(data))) {
                if (text.deflated()) {
                    ns += charge(node, Category.INFLATE, costs.inflateNanosPerByte() * text.bytes());
                }
                if (node.vehicle != null && loads.test(node.vehicle, text.uri()) && node.firstLoad(text.uri(), text.version())) {
                    ns += charge(node, Category.POLICY_LOAD, costs.loadNanosPerByte() * text.bytes());
                }
            }
        } else if (type == MessageType.DISCOVERY_REPLY.code()) {
            String vehicle = node.vehicle;
            ns += charge(node, Category.CONDITION,
                    costs.conditionNanos() * (vehicle == null ? 0 : newUavPolicies.applyAsInt(vehicle)));
        }
        return micros(ns);
    }

    /**
     * The HELLO {@code node} has from {@code sender}, if one came since its last datagram from it:
     * taken (verified; the first makes {@code node} its key pair, the second and third agree keys and
     * give the taker its session: half an {@code agreeNanos} each), and answered by the next (signed; its bytes go with
     * {@code node}'s next datagram). The CPU it costs, ns.
     */
    private double takeHello(Node node, Node sender, Handshake h) {
        boolean initiator = h.initiator == node.number;
        boolean due = initiator ? h.steps == 2 || h.steps == 4 : h.steps == 1 || h.steps == 3;
        if (!due) {
            return 0;
        }
        // HELLO 1 taken: a key pair; HELLO 2 or 3 taken: the agreement (agreeNanos is both, Calibration).
        double ns = costs.verifyNanos() + (h.steps == 4 ? 0 : costs.agreeNanos() / 2);
        if (h.steps < 4) {
            ns += costs.signNanos();
            long length = hello(node, sender);
            node.owedAirBytes += length;
        }
        h.steps++;
        return charge(node, Category.HANDSHAKE, ns);
    }

    /** A HELLO from {@code node} to {@code peer}, counted as sent: its length. */
    private long hello(Node node, Node peer) {
        long length = WireSizes.hello(node.vehicle == null ? "" : node.vehicle, mission, peer.vehicle == null ? "" : peer.vehicle);
        datagrams++;
        bytes += length;
        ledger.sentHello(length);
        return length;
    }

    /** The verification of {@code sender}'s credential, the first time {@code node} takes a signed datagram from it. */
    private double credential(Node node, Node sender) {
        return charge(node, Category.HANDSHAKE, credentialNanos(node, sender));
    }

    /** A credential verification if {@code node} has not verified {@code sender}'s yet (recording that it has), else 0. */
    private double credentialNanos(Node node, Node sender) {
        if (node.credentials.get(sender.number)) {
            return 0;
        }
        node.credentials.set(sender.number);
        return costs.verifyNanos();
    }

    private Handshake handshake(Node a, Node b) {
        long key = a.number < b.number ? (long) a.number << 32 | b.number : (long) b.number << 32 | a.number;
        return handshakes.computeIfAbsent(key, k -> new Handshake());
    }

    /**
     * The cell at {@code at} checks now the datagram it held from {@code from}: a signature
     * verification, and the credential's if it had not verified that vehicle's yet (a MAC if the
     * sender has a session with it), charged, as handshake work, with the cell's next datagram sent
     * or received.
     */
    public void heldChecked(Address at, Address from) {
        Node node = node(at);
        Node sender = node(from);
        ledger.heldChecked(node.number);
        if (handshake(node, sender).hasSession(sender)) {
            node.owedNanos += costs.macNanos();
        } else {
            node.owedNanos += costs.verifyNanos() + credentialNanos(node, sender);
        }
    }

    /** Charges {@code node} the work it did since its last datagram (checks of held ones), as handshake. */
    private double owed(Node node) {
        if (node.owedNanos == 0) {
            return 0;
        }
        double ns = node.owedNanos;
        node.owedNanos = 0;
        return charge(node, Category.HANDSHAKE, ns);
    }

    private double charge(Node node, Category category, double ns) {
        ledger.charge(node.number, category, ns);
        return ns;
    }

    /** Where the charged CPU went, per cell and category, and the datagrams by kind. */
    public CpuLedger ledger() {
        return ledger;
    }

    /** Datagrams sent so far (a broadcast counts once). */
    public long datagrams() {
        return datagrams;
    }

    /** Bytes of the datagrams sent so far. */
    public long bytes() {
        return bytes;
    }

    private double codec(int length) {
        return costs.codecNanos() + costs.codecNanosPerByte() * length;
    }

    private double mac(int length) {
        return costs.macNanos() + costs.macNanosPerByte() * length;
    }

    /** The message type of a datagram; for a fragment, the type of the message it is a piece of; -1 if unreadable. */
    int type(byte[] data) {
        return headers.type(data);
    }

    /**
     * Names the vehicle at {@code address}, whose envelopes' sizes follow from its name. Without it
     * the name is read from the first datagram that names its sender in its header (a discovery or
     * its reply: the other types leave it to the transport).
     */
    public void name(Address address, String vehicle) {
        Node node = node(address);
        node.vehicle = Objects.requireNonNull(vehicle, "vehicle");
        ledger.name(node.number, vehicle);
    }

    private Node node(Address address) {
        Node n = nodes.get(address);
        if (n == null) {
            n = new Node(nodes.size());
            nodes.put(address, n);
        }
        return n;
    }

    /** One address: a number of its own, the vehicle that sends from it (once it sent), and the credentials it verified. */
    private static final class Node {
        final int number;
        /** The numbers of the nodes whose credential this one has verified. */
        final BitSet credentials = new BitSet();
        String vehicle;
        /** Work done since this node's last datagram, to be charged with its next. */
        double owedNanos;
        /** HELLOs this node sent since its last datagram: their bytes go on its radio with its next. */
        long owedAirBytes;
        /** The policy replies this node was charged for, by sender and message id. */
        final Set<String> policyCopies = new HashSet<>();

        Node(int number) {
            this.number = number;
        }

        /** The policy files this node was charged the loading of. */
        final Set<String> loaded = new HashSet<>();

        /**
         * Whether version {@code version} of the file {@code uri} is loaded for the first time here:
         * a vehicle offered the same role by several managers gets its files from each, stores them,
         * and loads them once, as its role starts.
         */
        boolean firstLoad(String uri, int version) {
            return loaded.add(uri + "@" + version);
        }

        /** Whether the message {@code id} from {@code from} is new here (its first copy). */
        boolean firstCopy(Address from, long id) {
            return policyCopies.add(from + "#" + id);
        }
    }

    /**
     * The handshake of two cells, as their security layers run it: how many of its four HELLOs have
     * been sent (0: none, so no session), and which of the two sent the first.
     */
    private static final class Handshake {
        int steps;
        int initiator = -1;

        /**
         * Whether {@code node} has its session with the other of the two (it MACs what it sends): the
         * initiator once it took the second HELLO (so the third went), the other once it took the third.
         */
        boolean hasSession(Node node) {
            return steps >= (node.number == initiator ? 3 : 4);
        }
    }

    private static long micros(double nanos) {
        return Math.round(nanos / 1_000);
    }
}
