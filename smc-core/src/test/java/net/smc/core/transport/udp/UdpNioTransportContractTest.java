package net.smc.core.transport.udp;

/** The transport contract on real UDP over loopback, on Java NIO instead of epoll. */
class UdpNioTransportContractTest extends UdpTransportContractTest {

    @Override
    UdpEventLoop newLoop() {
        return UdpEventLoop.nio(2);
    }
}
