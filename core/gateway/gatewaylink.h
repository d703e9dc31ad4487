#pragma once

#include "gatewaycommands.h"
#include "gatewayconfig.h"
#include "gatewaystatistics.h"
#include "homeassistantdiscovery.h"

#include "core/watch/itemassembler.h"

#include <QList>
#include <QObject>
#include <QSet>

#include <optional>

#include <vector>

namespace Fatek {

class AlarmEngine;
class AlarmNorth;
class HistoryRecorder;
class HistorySink;
class MqttNorth;
class PlantConnection;
class Session;

// One connection of the gateway: its south, a plant connection (a direct link polling the
// connection's watch lists on its own worker thread), and its north, the MQTT side (MqttNorth),
// which consumes the plant connection's items like any other consumer, and its alarms: an
// AlarmEngine (another consumer of the plant connection) evaluating the items' alarm definitions,
// published and acknowledged through AlarmNorth on MqttNorth's broker connection, and its history:
// a HistoryRecorder (one more consumer) keeping what the items did in the gateway's store. What the
// gateway publishes and how it takes commands is MqttNorth's, GatewayCommands' and AlarmNorth's;
// this class starts and stops them in order. Lives in one thread.
class GatewayLink : public QObject
{
    Q_OBJECT

public:
    static constexpr int MaxPendingWrites = GatewayCommands::MaxPendingWrites;
    static constexpr int MaxCommandBytes = GatewayCommands::MaxCommandBytes;
    static constexpr int MaxAheadSec = GatewayCommands::MaxAheadSec;

    GatewayLink(const GatewayConnectionConfig &config, const QString &prefix,
                const MqttBrokerSettings &broker, bool readOnly, QObject *parent = nullptr);
    // Without stop() first, the broker gets no offline status before the disconnect.
    ~GatewayLink() override;

    QString name() const { return m_name; }
    // Opens the broker connection and then the PLC link; false (nothing started) when the broker
    // settings are not usable, with `error` saying why. The PLC link opens `pollDelayMs` later:
    // the gateway spreads its links' poll cycles over the interval instead of polling (and
    // publishing) all of them in the same instant (docs/performance.md).
    // The engine's alarms (restored by the journal, if any, before this) go out with the first
    // publications.
    bool start(Message *error, int pollDelayMs = 0);
    // Publishes the offline status, waits at most `timeoutMs` for the broker to take it, then
    // disconnects and closes the PLC link (accepted writes drain first); stopped() when done.
    void stop(int timeoutMs = 3000);
    bool isStopped() const { return m_stopped; }
    // Home Assistant's discovery configs for this link's items (retained, QoS 1): published when
    // the link starts and, as every retained topic, again after each reconnect. Before start().
    void setDiscovery(std::vector<HomeAssistantDiscovery::Entry> entries);
    // Clears the discovery configs of this link that `keep` does not hold (an empty retained
    // payload: Home Assistant removes the entity), before stop() when a reload removes items.
    void clearDiscovery(const QSet<QString> &keep);

    // Clears the alarm state topics of this link that `keep` does not hold (a reload removed
    // those alarms), before stop().
    void clearAlarms(const QSet<QString> &keep);
    // The connection's alarms (items with alarm definitions); the gateway's journal attaches to
    // it before start(), and then says so with awaitAlarmRestore(): the alarm states go out once
    // the journal's are back in the engine.
    AlarmEngine *alarms() const { return m_alarms; }
    void awaitAlarmRestore();
    // Records the connection's items with a history setting (and every other one with
    // `recordAll`) into `sink` (the gateway's HistoryWriter, which outlives this link), from
    // start() on. Before start().
    void setHistory(HistorySink *sink, const std::optional<HistorySetting> &recordAll);
    HistoryRecorder *history() const { return m_history; }

    GatewayStatistics statistics() const;
    PlantConnection *plant() const { return m_plant; }
    // The direct link's session (its counters and traffic log, for tests and tools).
    Session *session() const;

Q_SIGNALS:
    // One log line's worth (links up/down, broker up/down, every write accepted or refused).
    void logEvent(const Fatek::Message &event);
    void stopped();

private:
    QString m_name;
    PlantConnection *m_plant;
    MqttNorth *m_north;
    AlarmEngine *m_alarms;
    AlarmNorth *m_alarmNorth;
    HistoryRecorder *m_history = nullptr;
    QList<WatchedItem> m_items; // every item of the watch lists, for the history
    bool m_stopping = false;
    bool m_stopped = false;
};

} // namespace Fatek
