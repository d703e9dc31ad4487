#include "plctarget.h"

#include "core/session/changeverifier.h"
#include "core/session/session.h"

namespace Fatek {

PlcTarget::PlcTarget(PlcLink *link, quint8 station, const QString &connectionName)
    : m_link(link)
    , m_station(station)
    , m_connectionName(connectionName)
{}

Session *PlcTarget::session() const
{
    return m_link ? m_link->session() : nullptr;
}

bool PlcTarget::isReadOnly() const
{
    return m_link && m_link->isReadOnly();
}

int PlcTarget::timeoutMs() const
{
    const Session *s = session();
    return s ? s->settings().timeoutMs : 0;
}

std::optional<Protocol> PlcTarget::protocol() const
{
    const Session *s = session();
    if (!s || !s->isProtocolKnown())
        return std::nullopt;
    return s->protocol();
}

Protocol PlcTarget::framing() const
{
    if (const auto found = protocol())
        return *found;
    const Session *s = session();
    return s && s->settings().protocol == LinkSettings::ProtocolChoice::Binary ? Protocol::Binary
                                                                               : Protocol::Facon;
}

TrafficLog *PlcTarget::trafficLog() const
{
    const Session *s = session();
    return s ? s->trafficLog() : nullptr;
}

QMetaObject::Connection PlcTarget::onProtocolDetected(QObject *context,
                                                      const std::function<void()> &slot) const
{
    Session *s = session();
    if (!s)
        return {};
    return QObject::connect(s, &Session::protocolDetected, context, [slot] { slot(); });
}

RequestOptions PlcTarget::confirmedNow() const
{
    return ChangeVerifier::confirmedNow(session());
}

} // namespace Fatek
