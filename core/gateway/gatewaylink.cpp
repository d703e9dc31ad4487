#include "gatewaylink.h"

#include "core/plant/plantconnection.h"
#include "gatewaymessages.h"
#include "mqttnorth.h"

#include <QTimer>

namespace Fatek {

GatewayLink::GatewayLink(const GatewayConnectionConfig &config, const QString &prefix,
                         const MqttBrokerSettings &broker, bool readOnly, QObject *parent)
    : QObject(parent)
    , m_name(config.name)
    // Core refuses writes too, should a command ever slip past the gateway's checks.
    , m_plant(PlantConnection::direct(config.link, {readOnly, false}, this))
    , m_north(new MqttNorth(config, prefix, broker, readOnly, m_plant, this))
{
    connect(m_north, &MqttNorth::logEvent, this, &GatewayLink::logEvent);
    connect(m_north, &MqttNorth::stopped, this, [this] {
        m_plant->close();
        m_stopped = true;
        Q_EMIT logEvent(msg<MsgId::GatewayLogStopped>());
        Q_EMIT stopped();
    });
}

GatewayLink::~GatewayLink()
{
    // The north leaves the plant connection before the plant connection (and its session's
    // thread) goes.
    delete m_north;
}

bool GatewayLink::start(Message *error, int pollDelayMs)
{
    if (!m_north->start(error))
        return false;
    if (pollDelayMs > 0) {
        QTimer::singleShot(pollDelayMs, this, [this] {
            if (!m_stopping)
                m_plant->open();
        });
    } else {
        m_plant->open();
    }
    return true;
}

void GatewayLink::stop(int timeoutMs)
{
    if (m_stopping)
        return;
    m_stopping = true;
    m_north->stop(timeoutMs);
}

void GatewayLink::setDiscovery(std::vector<HomeAssistantDiscovery::Entry> entries)
{
    m_north->setDiscovery(std::move(entries));
}

void GatewayLink::clearDiscovery(const QSet<QString> &keep)
{
    m_north->clearDiscovery(keep);
}

GatewayStatistics GatewayLink::statistics() const
{
    return m_north->statistics();
}

Session *GatewayLink::session() const
{
    return m_plant->link()->session();
}

} // namespace Fatek
