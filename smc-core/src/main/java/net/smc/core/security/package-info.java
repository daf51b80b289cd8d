/**
 * Authentication for a team of vehicles: who may join (credentials from a mission authority), and
 * proof of who sent every datagram (signatures, session MACs, a team MAC), with stale and repeated
 * messages refused. The paper defers its public-key protocol (section IV-B); a real team cannot.
 *
 * <p>Start at {@link net.smc.core.security.SecureEndpoint}: sans-IO, it wraps outgoing payloads and
 * unwraps incoming datagrams into an authenticated sender and payload, or a counted
 * {@link net.smc.core.security.Rejection}. Payloads are opaque bytes, so any message codec sits on
 * top. {@link net.smc.core.security.SecureTransport} is the same layer as a
 * {@link net.smc.core.transport.Transport} decorator, for a cell that should not have to care.
 *
 * <p>Before a mission, an authority issues each vehicle a {@link net.smc.core.security.Credential}
 * for its key ({@code smc keys}; file formats in {@link net.smc.core.security.KeyFiles}). Then:
 * <pre>{@code
 * SigningIdentity me = new SigningIdentity(KeyFiles.readPrivateKey(keyFile), KeyFiles.readCredential(credFile));
 * TrustAnchor trust = new TrustAnchor(KeyFiles.readPublicKey(authorityPub), "rescue");
 * SecureEndpoint endpoint = SecureEndpoint.builder(me, trust, clock).build();
 * Transport secure = new SecureTransport(network.attach(address), endpoint);
 * secure.broadcast(discovery);      // signed, credential attached
 * secure.send(parent, heartbeat);   // MAC'd once the handshake that the first send started is done
 * }</pre>
 *
 * <p>The cryptography is Ed25519 and X25519 from Bouncy Castle's RFC 8032 and RFC 7748 code (the
 * same bytes as the JDK 17's providers, about ten times faster), the JDK's HMAC-SHA256 and AES-GCM,
 * and HKDF written here over HMAC. Wire and file formats, overheads, the handshake and the failure cases are
 * in <a href="doc-files/security.md">the security design note</a>.
 */
package net.smc.core.security;
