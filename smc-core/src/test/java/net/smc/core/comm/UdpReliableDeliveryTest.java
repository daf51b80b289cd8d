package net.smc.core.comm;

/** The reliable-delivery suite over Netty UDP on loopback, with faults injected on the sending side. */
class UdpReliableDeliveryTest extends ReliableDeliveryContract {

    @Override
    protected Net newNet(Net.Faults faults, long seed) {
        return new UdpNet(faults, seed, SETTINGS);
    }
}
