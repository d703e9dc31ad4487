#include "transport.h"

#include "serialtransport.h"
#include "tcptransport.h"
#include "udptransport.h"

namespace Fatek {

Transport *Transport::create(const LinkSettings &settings, QObject *parent)
{
    switch (settings.kind) {
    case LinkSettings::Kind::Serial: return new SerialTransport(settings, parent);
    case LinkSettings::Kind::Tcp: return new TcpTransport(settings, parent);
    case LinkSettings::Kind::Udp: return new UdpTransport(settings, parent);
    }
    return nullptr;
}

} // namespace Fatek
