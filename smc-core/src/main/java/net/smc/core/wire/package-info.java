/**
 * The bounds-checked binary reader and writer under every wire format of the project: the
 * datagram codec ({@code net.smc.core.message}), the capability forms ({@code net.smc.core.capability})
 * and the credential and protected-datagram forms ({@code net.smc.core.security}).
 *
 * <p>{@link net.smc.core.wire.ByteReader} reads big-endian fields from a byte range and checks every
 * length against the bytes left before it allocates anything; a format passes it a
 * {@link net.smc.core.wire.WireErrors}, which turns a {@link net.smc.core.wire.WireProblem} into that
 * format's exception and wording. {@link net.smc.core.wire.ByteWriter} writes big-endian fields into
 * an array up to a limit, growing it if asked to. {@link net.smc.core.wire.StrictUtf8} is the strict
 * UTF-8 both use. This package knows no format: formats build on it, never the other way.
 *
 * <pre>{@code
 * ByteReader<IOException> in = new ByteReader<>((problem, at, field, rule) ->
 *         new IOException(field + " at byte " + at + ": " + rule), bytes, 0, bytes.length);
 * long stamp = in.i64("timestamp");   // IOException "timestamp at byte 0: truncated: needs 8 bytes, 3 left"
 * }</pre>
 */
package net.smc.core.wire;
