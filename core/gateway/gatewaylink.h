#pragma once

#include "core/mqtt/gatewaypayload.h"
#include "core/session/sessiontypes.h"
#include "core/watch/itemassembler.h"
#include "delayhistogram.h"
#include "gatewayconfig.h"
#include "gatewaypublisher.h"
#include "gatewaystatistics.h"
#include "homeassistantdiscovery.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QSet>
#include <QTimer>

#include <deque>
#include <vector>

namespace Fatek {

class MqttClient;
class Session;

// One connection of the gateway: a Session polling the connection's watch lists (on its own
// worker thread) and an MqttClient (its own network thread) publishing every item, the link's
// status and statistics, and taking write commands. Lives in one thread; both sides' signals
// arrive there, so nothing here is shared between threads.
//
// Items are published (retained, QoS 0) when their words or quality change, and all again after
// every broker (re)connect; an item that changes again before it went out goes once, newest state.
// Good means read in the cycle that published it; when the PLC link goes down every item is
// published stale with the reason. The status goes connecting -> up -> down (reason) -> up ...; the
// broker's will (offline) covers a gateway that dies, stop() publishes offline itself.
class GatewayLink : public QObject
{
    Q_OBJECT

public:
    // Writes waiting for the PLC link at most; more are refused (a peer flooding /set topics).
    static constexpr int MaxPendingWrites = 100;
    // Longest /set payload taken.
    static constexpr int MaxCommandBytes = 4096;
    // How far a command's "time" may lie ahead of the gateway's clock. Clocks of machines that
    // sync over NTP differ by milliseconds, by a few seconds when one drifted; further ahead the
    // time is wrong, and taken as it is it would keep a command alive past commandMaxAgeSec for
    // as long (a time in 2099 never expired). 5 s stretches the 10 s default by half at most.
    static constexpr int MaxAheadSec = 5;
    // Set topics whose last command is remembered (to know the broker's retained copy of one
    // already answered); beyond it the memory starts again.
    static constexpr int MaxRememberedCommands = 256;

    GatewayLink(const GatewayConnectionConfig &config, const QString &prefix,
                const MqttBrokerSettings &broker, bool readOnly, QObject *parent = nullptr);
    // Without stop() first, the broker gets no offline status before the disconnect.
    ~GatewayLink() override;

    QString name() const { return m_config.name; }
    // Opens the PLC link and the broker connection; false (nothing started) when the broker
    // settings are not usable, with `error` saying why. The PLC link opens `pollDelayMs` later:
    // the gateway spreads its links' poll cycles over the interval instead of polling (and
    // publishing) all of them in the same instant (docs/performance.md).
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

    GatewayStatistics statistics() const;
    Session *session() const { return m_session; }

Q_SIGNALS:
    // One log line's worth (links up/down, broker up/down, every write accepted or refused).
    void logEvent(const Fatek::Message &event);
    void stopped();

private:
    struct Item
    {
        ItemValues values;
        QString topic;
        GatewayPublisher::TopicId topicId = 0; // the topic, named once to the publisher
        QByteArray goodHead; // the payload's start while good (written at the first good value)
        std::vector<std::uint32_t> words; // empty until every element was read once
        ValueQuality quality = ValueQuality::Stale;
        Message error;
        QDateTime time;
        bool published = false;
        bool dirty = false; // changed since last handed to the publisher (in m_dirty)
    };

    void onValues(const QList<WatchValue> &values);
    void onLinkState(LinkState state, const Message &reason);
    void onCommand(const QString &topic, const QByteArray &payload, bool retained, bool queued);
    // Why a command is too old to carry out (empty: it is not).
    Message tooOld(const GatewayPayload::SetCommand &command, bool queued) const;
    // How old the command is: by its own time, and by the broker's outage when it was kept there.
    qint64 commandAgeMs(const GatewayPayload::SetCommand &command, bool queued) const;
    void update(std::size_t index, const std::vector<std::uint32_t> &words, ValueQuality quality,
                const Message &error, const QDateTime &time);
    void markDirty(std::size_t index);
    void publishDirty();
    void publishNextDirty();
    void publishItem(Item &item);
    void publishStatus(GatewayPayload::LinkStatus state, const Message &reason);
    void publishStatistics();
    void refuse(GatewayPayload::Reply reply, const Message &why);
    void answer(const GatewayPayload::Reply &reply);
    void checkStopped();

    GatewayConnectionConfig m_config;
    QString m_prefix;
    bool m_readOnly;
    QString m_linkText;
    Session *m_session;
    MqttClient *m_client;
    GatewayPublisher *m_publisher;
    std::vector<Item> m_items;
    std::vector<HomeAssistantDiscovery::Entry> m_discovery;
    ItemAssembler m_assembler; // joins the session's element values into m_items' values
    QHash<QString, std::size_t> m_itemOfTopic;
    std::deque<std::size_t> m_dirty; // items to publish, oldest change first
    bool m_publishQueued = false;
    QTimer m_publishRetry; // publishDirty() again while the publisher has no room
    quint64 m_coalesced = 0;
    DelayHistogram m_delays; // since the last statistics
    GatewayPayload::LinkStatus m_status = GatewayPayload::LinkStatus::Connecting;
    bool m_everUp = false;
    int m_pendingWrites = 0;
    GatewayStatistics m_counters;
    QTimer m_statisticsTimer;
    QTimer m_stopTimer;
    QElapsedTimer m_stopClock;
    int m_stopTimeoutMs = 0;
    bool m_stopping = false;
    bool m_brokerDown = true;
    QDateTime m_brokerDownAt; // when the link to the broker last went down (invalid: never)
    // The last command per set topic (payload), for onCommand's retained copies.
    QHash<QString, QByteArray> m_lastCommand;
    bool m_stopped = false;
};

} // namespace Fatek
