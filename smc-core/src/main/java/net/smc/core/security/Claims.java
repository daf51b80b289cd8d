package net.smc.core.security;

import java.util.Objects;

/**
 * What a mission authority vouches for in a {@link Credential}: this vehicle holds this key and
 * may take part in this mission during this time.
 *
 * @param vehicleId       the vehicle's identity, 1 to 64 bytes of UTF-8
 * @param vehicleKey      the vehicle's Ed25519 public key
 * @param mission         the mission it may join, 1 to 64 bytes of UTF-8
 * @param notBeforeMillis the first instant it is valid, epoch milliseconds
 * @param expiresMillis   the first instant it is no longer valid, epoch milliseconds; after {@code notBeforeMillis}
 */
public record Claims(String vehicleId, VerificationKey vehicleKey, String mission, long notBeforeMillis, long expiresMillis) {

    /** @throws IllegalArgumentException naming the field, its value and the rule it breaks */
    public Claims {
        WireNames.encode(vehicleId, "credential", "vehicle id");
        Objects.requireNonNull(vehicleKey, "vehicleKey");
        WireNames.encode(mission, "credential", "mission");
        if (expiresMillis <= notBeforeMillis) {
            throw new IllegalArgumentException("credential of '" + vehicleId + "': expires at " + expiresMillis
                    + " ms, not after its not-before of " + notBeforeMillis + " ms; it must expire after it becomes valid");
        }
    }
}
