package net.smc.demo;

import net.smc.core.transport.Address;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * {@code ADDR:PORT} as an {@link Address}, for the options that name a node's UDP address
 * ({@code status --node}, {@code node --bind}, {@code node --broadcast}); anything else is a usage
 * error saying what was expected.
 */
final class AddressConverter implements ITypeConverter<Address> {
    @Override
    public Address convert(String value) {
        try {
            return Address.parse(value);
        } catch (IllegalArgumentException e) {
            throw new TypeConversionException("'" + value + "' is not ADDR:PORT; expected an IPv4 address and a "
                    + "UDP port 1-65535, e.g. 127.0.0.1:4000");
        }
    }
}
