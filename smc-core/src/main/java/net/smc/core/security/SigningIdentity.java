package net.smc.core.security;

import java.util.Objects;

/**
 * Who a vehicle is on the network: its signing key and the credential that vouches for it.
 *
 * @param key        the vehicle's Ed25519 key pair
 * @param credential its credential; it must be for {@code key}'s public half
 */
public record SigningIdentity(SigningKey key, Credential credential) {

    /** @throws IllegalArgumentException when the credential vouches for another key */
    public SigningIdentity {
        Objects.requireNonNull(key, "key");
        Objects.requireNonNull(credential, "credential");
        if (!credential.vehicleKey().equals(key.verificationKey())) {
            throw new IllegalArgumentException("credential of '" + credential.vehicleId() + "' is for key "
                    + credential.vehicleKey().id() + ", not for the signing key " + key.verificationKey().id()
                    + "; a vehicle must hold the key its credential names");
        }
    }

    /** The vehicle's id, as its credential gives it. */
    public String id() {
        return credential.vehicleId();
    }
}
