#pragma once

#include "core/mqtt/gatewaypayload.h"
#include "core/plant/plantconsumer.h"
#include "delayhistogram.h"
#include "gatewayconfig.h"
#include "gatewaypublisher.h"
#include "gatewaystatistics.h"
#include "homeassistantdiscovery.h"
#include "stationactivity.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QTimer>

#include <deque>
#include <vector>

namespace Fatek {

class GatewayCommands;
class MqttClient;
class PlantConnection;

// The MQTT side of one gateway connection, a consumer of its plant connection like any other:
// an MqttClient (its own network thread) publishing every item of the connection's watch lists,
// the link's status and statistics, Home Assistant's discovery, and taking write commands
// (GatewayCommands). Lives in the plant connection's thread.
//
// Items are published (retained, QoS 0) when their words or quality change, and all again after
// every broker (re)connect; an item that changes again before it went out goes once, newest state.
// Good means read in the cycle that published it; when the PLC link goes down every item is
// published stale with the reason. The status goes connecting -> up -> down (reason) -> up ...
// (down also while the link is up and no station answers: StationActivity, which also logs what
// the stations do); the broker's will (offline) covers a gateway that dies, stop() publishes
// offline itself.
class MqttNorth : public QObject, public PlantConsumer
{
    Q_OBJECT

public:
    MqttNorth(const GatewayConnectionConfig &config, const QString &prefix,
              const MqttBrokerSettings &broker, bool readOnly, PlantConnection *plant,
              QObject *parent = nullptr);
    ~MqttNorth() override;

    // Subscribes the items to the plant connection and opens the broker connection; false
    // (nothing started) when the broker settings are not usable, with `error` saying why.
    bool start(Message *error);
    // Publishes what was read and the offline status, waits at most `timeoutMs` for the broker to
    // take it, then disconnects; stopped() when done.
    void stop(int timeoutMs);
    bool isStopped() const { return m_stopped; }
    void setDiscovery(std::vector<HomeAssistantDiscovery::Entry> entries);
    void clearDiscovery(const QSet<QString> &keep);
    GatewayStatistics statistics() const;
    // The broker connection and its publisher, shared with the link's other north side (its
    // alarms: AlarmNorth) so that one connection carries one client id and one will.
    MqttClient *client() const { return m_client; }
    GatewayPublisher *publisher() const { return m_publisher; }

    void plantValues(const QList<WatchItemValue> &values) override;
    void plantLinkState(LinkState state, const Message &reason) override;

Q_SIGNALS:
    void logEvent(const Fatek::Message &event);
    void stopped();

private:
    struct Item
    {
        ItemValues values;
        GatewayPublisher::TopicId topicId = 0; // the topic, named once to the publisher
        QByteArray goodHead; // the payload's start while good (written at the first good value)
        std::vector<std::uint32_t> words; // empty until every element was read once
        ValueQuality quality = ValueQuality::Stale;
        Message error;
        QDateTime time;
        bool published = false;
        bool dirty = false; // changed since last handed to the publisher (in m_dirty)
    };

    void update(std::size_t index, const std::vector<std::uint32_t> &words, ValueQuality quality,
                const Message &error, const QDateTime &time);
    void markDirty(std::size_t index);
    void publishDirty();
    void publishNextDirty();
    void publishItem(Item &item);
    void publishStatus(GatewayPayload::LinkStatus state, const Message &reason);
    // Status down while no station answers, up again when one does.
    void updateSilence();
    void publishStatistics();
    void checkStopped();

    GatewayConnectionConfig m_config;
    QString m_prefix;
    QString m_linkText;
    QPointer<PlantConnection> m_plant;
    MqttClient *m_client;
    GatewayPublisher *m_publisher;
    GatewayCommands *m_commands;
    std::vector<Item> m_items;
    QHash<QString, std::size_t> m_itemOfTopic;
    QList<WatchedItem> m_watched; // m_items as subscribed: key m_firstKey + index
    std::uint64_t m_firstKey = 0;
    std::vector<HomeAssistantDiscovery::Entry> m_discovery;
    std::deque<std::size_t> m_dirty; // items to publish, oldest change first
    bool m_publishQueued = false;
    QTimer m_publishRetry; // publishDirty() again while the publisher has no room
    quint64 m_coalesced = 0;
    DelayHistogram m_delays; // since the last statistics
    GatewayPayload::LinkStatus m_status = GatewayPayload::LinkStatus::Connecting;
    StationActivity m_activity;
    bool m_silent = false; // the status is down because no station answers
    QTimer m_statisticsTimer;
    QTimer m_stopTimer;
    QElapsedTimer m_stopClock;
    int m_stopTimeoutMs = 0;
    bool m_stopping = false;
    bool m_stopped = false;
};

} // namespace Fatek
