package net.smc.core.cell;

import java.util.Collections;
import java.util.EnumSet;
import java.util.Set;
import java.util.function.BooleanSupplier;

import net.smc.core.message.DecodeResult;
import net.smc.core.message.Discovery;
import net.smc.core.message.DiscoveryReply;
import net.smc.core.message.MessageDecoder;
import net.smc.core.message.MessageType;
import net.smc.core.message.SharedDecodes;
import net.smc.core.message.Withdrawal;
import net.smc.core.transport.Address;

/**
 * What a cell reads of a datagram before its authenticating transport has checked it (part of
 * {@link TeamProtocol}): the discoveries it would ignore whoever sent them, dropped before their
 * check, and the discovery replies a manager reads to choose whom to contact, and their
 * withdrawals, held unchecked.
 */
final class UnverifiedReads {
    /**
     * The types read here, before the transport has checked who sent them: they name their sender
     * in their header, and every other type leaves it to the transport, which proves it
     * ({@link net.smc.core.comm.CommunicationManager.Builder#senderLeftToTransport}). A datagram of
     * another type that left its sender out does not decode here, so it is neither dropped unchecked
     * nor held: it is checked as it comes.
     */
    static final Set<MessageType> READ_UNCHECKED = Collections.unmodifiableSet(
            EnumSet.of(MessageType.DISCOVERY, MessageType.DISCOVERY_REPLY, MessageType.WITHDRAWAL));

    /** Where a message's type code sits in its datagram (after the magic and the version: {@code Header}). */
    private static final int TYPE_AT = 3;

    private final TeamContext ctx;
    private final Assignee assignee;
    private final Recruiter recruiter;
    /** Whether the cell stopped: it then reads nothing more. */
    private final BooleanSupplier stopped;
    /** Decodes datagrams not yet authenticated: its own, so the cell's reassembly is untouched. */
    private final MessageDecoder peek;

    UnverifiedReads(TeamContext ctx, Assignee assignee, Recruiter recruiter, BooleanSupplier stopped) {
        this.ctx = ctx;
        this.assignee = assignee;
        this.recruiter = recruiter;
        this.stopped = stopped;
        this.peek = new MessageDecoder(ctx.clock()::nowMillis);
    }

    /** Shares the decodes of {@link #ignores} with the process's other cells (null: none). */
    void share(SharedDecodes table) {
        peek.share(table);
    }

    /**
     * Whether this cell would do nothing, now, with the message in {@code data[offset, offset + length)}
     * (one datagram as the Communication-Manager decodes it, read in place) whoever really sent it: a discovery it would not answer
     * ({@link Assignee#ignores}: the vehicle has a parent, or could hold no role that manager
     * manages). In a large team every cell hears every manager's discovery and answers few of them;
     * checking the signature of each (an Ed25519 verification, and the sender's credential the first
     * time) is most of what a busy manager's CPU does while the team forms. An authenticating
     * transport asks this before its checks and drops what it is told ({@code
     * AuthenticatingTransport.setUnverifiedFilter}): dropping an authentic message this cell would
     * ignore changes nothing, and a forged one would have been refused. It must never answer true for
     * a message the cell acts on, or a forger could choose what the cell hears: so only discoveries,
     * only by the same test {@link Assignee#onDiscovery} applies, and never a fragment or anything
     * that does not decode.
     */
    boolean ignores(byte[] data, int offset, int length) {
        if (length <= TYPE_AT || (data[offset + TYPE_AT] & 0xFF) != MessageType.DISCOVERY.code()) {
            return false;
        }
        return peek.decode(data, offset, length) instanceof DecodeResult.Decoded d && d.envelope().body() instanceof Discovery discovery
                && assignee.ignores(d.envelope().sender(), discovery);
    }

    /**
     * Whether the authenticating transport should hold the payload {@code data[offset, offset + length)}
     * (read in place) unchecked for this cell to read first ({@code AuthenticatingTransport.holdUnverified}): a discovery reply (not a fragment
     * of one). A manager reads the answers to its discovery to choose whom to contact, and checks (a
     * credential verification, then a key agreement as it contacts the vehicle) only those it tries
     * to seat ({@link Recruiter#onUnverifiedReply}); the reply itself is acted on only once checked.
     * Or a withdrawal of such a reply ({@link Recruiter#onWithdrawal}), held in its place (the
     * transport holds the newest datagram per source): unchecked it is not acted on; if the manager
     * comes to that vehicle, what it checks is the withdrawal, and the vehicle is passed over; if a
     * seat is already on its way to that vehicle, it is checked at once, and the seat opens again.
     */
    boolean reads(byte[] data, int offset, int length) {
        if (length <= TYPE_AT) {
            return false;
        }
        int type = data[offset + TYPE_AT] & 0xFF;
        return type == MessageType.DISCOVERY_REPLY.code() || type == MessageType.WITHDRAWAL.code();
    }

    /**
     * A payload held unchecked ({@link #reads}) from {@code from}: who claims to answer, for the
     * recruiter's choice; or who claims to withdraw its answer, for a recruiter waiting on that
     * vehicle's answer to an assignment ({@link Recruiter#onUnverifiedWithdrawal}). A withdrawal held
     * has displaced the answer held from the same source.
     */
    void onHeld(Address from, byte[] datagram) {
        if (stopped.getAsBoolean() || !(peek.decode(datagram) instanceof DecodeResult.Decoded d)
                || d.envelope().sender().equals(ctx.self())) {
            return;
        }
        if (d.envelope().body() instanceof DiscoveryReply r) {
            recruiter.onUnverifiedReply(d.envelope().sender(), from, r);
        } else if (d.envelope().body() instanceof Withdrawal w) {
            recruiter.onUnverifiedWithdrawal(d.envelope().sender(), from, w);
        }
    }
}
