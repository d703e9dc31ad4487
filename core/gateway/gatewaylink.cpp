#include "gatewaylink.h"

#include "alarmnorth.h"
#include "core/alarm/alarmengine.h"
#include "core/history/historyrecorder.h"
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
    , m_alarms(new AlarmEngine(config.name, this))
{
    QList<WatchedItem> alarmed;
    for (const WatchTableSpec &table : config.tables) {
        for (const WatchItemSpec &spec : table.items) {
            if (!spec.alarms.isEmpty())
                alarmed.append({0, spec, table.intervalMs});
            m_items.append({0, spec, table.intervalMs});
        }
    }
    m_alarms->setItems(alarmed);
    m_alarmNorth
        = new AlarmNorth(config, prefix, m_alarms, m_north->client(), m_north->publisher(), this);
    connect(m_alarmNorth, &AlarmNorth::logEvent, this, &GatewayLink::logEvent);
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
    // The consumers leave the plant connection before the plant connection (and its session's
    // thread) goes; the alarms' north before the broker connection it shares. The recorder keeps
    // an Off sample for its items as it goes: nothing is recorded from here on.
    delete m_history;
    delete m_alarmNorth;
    delete m_alarms;
    delete m_north;
}

bool GatewayLink::start(Message *error, int pollDelayMs)
{
    if (!m_north->start(error))
        return false;
    m_alarmNorth->start();
    m_alarms->attach(m_plant);
    if (m_history)
        m_history->attach(m_plant);
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
    // The alarms keep their states (the journal has them) rather than see the link close.
    m_alarms->attach(nullptr);
    m_alarmNorth->stop();
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

void GatewayLink::awaitAlarmRestore()
{
    m_alarmNorth->awaitRestore();
}

void GatewayLink::setHistory(HistorySink *sink, const std::optional<HistorySetting> &recordAll)
{
    delete m_history;
    m_history = new HistoryRecorder(m_name, sink, this);
    m_history->setRecordAll(recordAll);
    m_history->setItems(m_items);
}

void GatewayLink::clearAlarms(const QSet<QString> &keep)
{
    m_alarmNorth->clearStates(keep);
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
