package net.smc.core.security;

import java.util.HashMap;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

import net.smc.core.transport.Address;
import net.smc.core.transport.Clock;
import net.smc.core.transport.ForwardingTransport;
import net.smc.core.transport.Receiver;
import net.smc.core.transport.Transport;

/**
 * Authentication as a simulation can afford it: the credential check is real, the per-datagram
 * cryptography is not. In simulation the network itself knows which endpoint sent a datagram (no
 * one can forge a source address of the in-memory network), so once a vehicle's credential has been
 * verified against the trust anchor, everything from its address is vouched for as coming from it.
 * A vehicle whose credential does not verify (a foreign authority, a bad signature, expired, another
 * mission) is never vouched for: what it sends is dropped and counted, exactly as
 * {@link SecureTransport} drops what fails its checks.
 *
 * <p>This models an ideal {@link SecureTransport}: same delivery rule (only authenticated payloads,
 * with their proven sender), none of its cost (about 1 ms per Ed25519 signature or verification),
 * which lets thousands of simulated team runs fit in a test run. The real one is exercised by its own
 * tests and by simulation runs that use it.
 *
 * <p>One instance serves one simulated network; all calls on the simulation's thread.
 */
public final class IdealAuthentication {
    private final TrustAnchor trust;
    private final Clock clock;
    private final Map<Address, Credential> vouched = new HashMap<>();
    private final Map<String, Credential> byVehicle = new HashMap<>();
    private long dropped;

    public IdealAuthentication(TrustAnchor trust, Clock clock) {
        this.trust = Objects.requireNonNull(trust, "trust");
        this.clock = Objects.requireNonNull(clock, "clock");
    }

    /**
     * Wraps a vehicle's endpoint, presenting {@code credential} for it. The credential is checked
     * now; when it fails, the endpoint still sends, but nobody accepts what it sends.
     *
     * @return the endpoint, and whether the credential was accepted
     */
    public Endpoint wrap(Transport inner, Credential credential) {
        Objects.requireNonNull(inner, "inner");
        Objects.requireNonNull(credential, "credential");
        CredentialStatus status = trust.verify(credential, clock.nowMillis());
        if (status == CredentialStatus.VALID) {
            vouched.put(inner.localAddress(), credential);
            byVehicle.put(credential.vehicleId(), credential);
        } else {
            vouched.remove(inner.localAddress());
        }
        return new Endpoint(inner, status);
    }

    /** Payloads dropped because their sender was not vouched for. */
    public long dropped() {
        return dropped;
    }

    /** One vehicle's endpoint: delivers only what vouched-for vehicles sent. */
    public final class Endpoint extends ForwardingTransport implements AuthenticatingTransport {
        private final CredentialStatus status;
        private AuthenticatedReceiver receiver;

        private Endpoint(Transport inner, CredentialStatus status) {
            super(inner);
            this.status = status;
            inner.setReceiver(this::onDatagram);
        }

        /** What the check of this endpoint's own credential found. */
        public CredentialStatus credentialStatus() {
            return status;
        }

        @Override
        public void setReceiver(Receiver plain) {
            Objects.requireNonNull(plain, "receiver");
            setAuthenticatedReceiver((sender, from, protection, payload) -> plain.onDatagram(from, payload));
        }

        @Override
        public void setAuthenticatedReceiver(AuthenticatedReceiver receiver) {
            if (this.receiver != null) {
                throw new IllegalStateException("a receiver is already set on the endpoint at " + localAddress());
            }
            this.receiver = Objects.requireNonNull(receiver, "receiver");
        }

        @Override
        public Optional<Credential> credentialOf(String peer) {
            return Optional.ofNullable(byVehicle.get(peer));
        }

        private void onDatagram(Address from, byte[] data) {
            Credential sender = vouched.get(from);
            if (sender == null || receiver == null) {
                dropped++;
                return;
            }
            receiver.onMessage(sender.vehicleId(), from, Protection.PAIR_MAC, data);
        }
    }
}
