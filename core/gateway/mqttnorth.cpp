#include "mqttnorth.h"

#include "core/mqtt/gatewaytopics.h"
#include "core/mqtt/mqttclient.h"
#include "core/mqtt/mqttmessages.h"
#include "core/plant/plantconnection.h"
#include "gatewaycommands.h"
#include "gatewaymessages.h"

namespace Fatek {

using GatewayPayload::LinkStatus;

namespace {

// A persistent session (issue 33): with a client id fixed per connection the broker keeps the
// subscription and the QoS 1 commands sent while the gateway is away, so that every command is
// answered (carried out, or refused as too old) when it comes back.
MqttBrokerSettings persistentSession(MqttBrokerSettings broker, const QString &prefix,
                                     const QString &connection)
{
    const QString base
        = broker.clientId.isEmpty() ? QStringLiteral("fatek-gateway-") + prefix : broker.clientId;
    broker.clientId = base + QLatin1Char('-') + connection;
    broker.cleanSession = false;
    return broker;
}

} // namespace

MqttNorth::MqttNorth(const GatewayConnectionConfig &config, const QString &prefix,
                     const MqttBrokerSettings &broker, bool readOnly, PlantConnection *plant,
                     QObject *parent)
    : QObject(parent)
    , m_config(config)
    , m_prefix(prefix)
    , m_linkText(config.link.toString())
    , m_plant(plant)
    , m_client(new MqttClient(persistentSession(broker, prefix, config.name), this))
    , m_publisher(new GatewayPublisher(m_client, this))
{
    // Keys m_firstKey + i find item i without a look-up.
    std::size_t count = 0;
    for (const WatchTableSpec &table : m_config.tables)
        count += static_cast<std::size_t>(table.items.size());
    m_firstKey = WatchedItem::newKeys(count);
    for (const WatchTableSpec &table : m_config.tables) {
        for (const WatchItemSpec &spec : table.items) {
            Item item;
            item.values = ItemValues(spec);
            const QString topic
                = GatewayTopics::item(prefix, config.name, spec.station, spec.address);
            item.topicId = m_publisher->retainedTopic(topic, 0);
            m_watched.append({m_firstKey + m_items.size(), spec, table.intervalMs});
            m_itemOfTopic.insert(topic, m_items.size());
            m_items.push_back(std::move(item));
        }
    }
    connect(m_client, &MqttClient::connected, this, [this] {
        Q_EMIT logEvent(msg<MsgId::GatewayLogBrokerUp>(m_client->settings().toUrl().toStdString()));
    });
    connect(m_client, &MqttClient::disconnected, this, [this](const Message &reason) {
        if (!m_stopping)
            Q_EMIT logEvent(msg<MsgId::GatewayLogBrokerDown>(reason));
    });

    // The will's time is that of the connect that left it with the broker (docs/gateway.md, "a
    // historian"): the broker publishes it later, when it finds this connection dead.
    m_client->setWill(
        GatewayTopics::status(prefix, config.name),
        [link = m_linkText] {
            return GatewayPayload::encodeStatus(
                {LinkStatus::Offline, link, {}, QDateTime::currentDateTimeUtc()});
        },
        1, true);
    const auto watchedAt = [this](const QString &topic) -> const WatchItemSpec * {
        const auto it = m_itemOfTopic.constFind(topic);
        return it == m_itemOfTopic.cend() ? nullptr : &m_items[*it].values.item();
    };
    m_commands = new GatewayCommands(config, prefix, readOnly, watchedAt, m_client, m_publisher,
                                     plant, this);
    connect(m_commands, &GatewayCommands::logEvent, this, &MqttNorth::logEvent);

    m_statisticsTimer.setInterval(config.statisticsIntervalMs);
    connect(&m_statisticsTimer, &QTimer::timeout, this, &MqttNorth::publishStatistics);
    m_stopTimer.setInterval(20);
    connect(&m_stopTimer, &QTimer::timeout, this, &MqttNorth::checkStopped);
    m_publishRetry.setInterval(5);
    m_publishRetry.setSingleShot(true);
    connect(&m_publishRetry, &QTimer::timeout, this, &MqttNorth::publishDirty);
}

MqttNorth::~MqttNorth()
{
    // Signals of the children must not reach this half-destroyed object.
    disconnect(m_client, nullptr, this, nullptr);
    if (m_plant)
        m_plant->unsubscribe(this);
}

bool MqttNorth::start(Message *error)
{
    if (!m_client->open()) {
        *error = m_client->openError();
        return false;
    }
    m_plant->subscribe(this, m_watched);
    publishStatus(LinkStatus::Connecting, {});
    for (const HomeAssistantDiscovery::Entry &entry : m_discovery)
        m_publisher->publishRetained(entry.topic, entry.payload);
    m_statisticsTimer.start();
    return true;
}

void MqttNorth::setDiscovery(std::vector<HomeAssistantDiscovery::Entry> entries)
{
    m_discovery = std::move(entries);
}

void MqttNorth::clearDiscovery(const QSet<QString> &keep)
{
    for (const HomeAssistantDiscovery::Entry &entry : m_discovery) {
        if (!keep.contains(entry.topic))
            m_publisher->publishRetained(entry.topic, {});
    }
}

void MqttNorth::stop(int timeoutMs)
{
    if (m_stopping)
        return;
    m_stopping = true;
    m_commands->stop();
    m_statisticsTimer.stop();
    m_plant->unsubscribe(this);
    // What was read goes out before the offline status (the publisher keeps it meanwhile).
    m_publishRetry.stop();
    while (!m_dirty.empty())
        publishNextDirty();
    publishStatistics();
    publishStatus(LinkStatus::Offline, {});
    m_stopTimeoutMs = timeoutMs;
    m_stopClock.start();
    m_stopTimer.start();
    checkStopped();
}

void MqttNorth::checkStopped()
{
    // Done when the broker took everything (outstanding 0: QoS 1 acknowledged), when there is no
    // broker to wait for, or at the bound.
    const bool delivered = m_publisher->waiting() == 0 && m_client->outstanding() == 0;
    if (m_stopped
        || (!delivered && m_client->isConnected() && !m_stopClock.hasExpired(m_stopTimeoutMs)))
        return;
    m_stopTimer.stop();
    m_client->close();
    m_stopped = true;
    Q_EMIT stopped();
}

GatewayStatistics MqttNorth::statistics() const
{
    GatewayStatistics s;
    const GatewayCommands::Counters writes = m_commands->counters();
    s.writesAccepted = writes.accepted;
    s.writesRefused = writes.refused;
    s.writesFailed = writes.failed;
    s.writesUnknown = writes.unknown;
    const GatewayPublisher::Counters c = m_publisher->counters();
    s.published = c.published;
    // Replaced in this link (before encoding), in the publisher and in the client's queue.
    s.superseded = c.superseded + m_coalesced + m_client->superseded();
    s.repliesDropped = c.repliesDropped;
    s.waiting = static_cast<quint64>(m_publisher->waiting());
    s.delayP50Ms = m_delays.percentile(0.50);
    s.delayP99Ms = m_delays.percentile(0.99);
    s.delayMaxMs = m_delays.max();
    return s;
}

void MqttNorth::plantValues(const QList<WatchItemValue> &values)
{
    if (m_stopping)
        return;
    // An item whose elements were never all read has no words: nothing invented goes out.
    for (const WatchItemValue &v : values) {
        const std::uint64_t index = v.key - m_firstKey;
        if (v.key < m_firstKey || index >= m_items.size())
            continue; // not one of ours (the plant hands out only ours; kept safe all the same)
        update(static_cast<std::size_t>(index), v.hasValue ? v.words : std::vector<std::uint32_t>{},
               v.quality, v.error, v.time);
    }
}

void MqttNorth::update(std::size_t index, const std::vector<std::uint32_t> &words,
                       ValueQuality quality, const Message &error, const QDateTime &time)
{
    Item &item = m_items[index];
    const WatchItemSpec &spec = item.values.item();
    for (const Message &line : m_activity.item(spec.station, spec.address, quality, error))
        Q_EMIT logEvent(line);
    updateSilence();
    // A stale item goes out again when its reason changes kind (no answer -> station demoted),
    // not for every new detail (the next try's time).
    const bool changed = !item.published || words != item.words || quality != item.quality
                         || (quality == ValueQuality::Error && error != item.error)
                         || (quality != ValueQuality::Good && error.id != item.error.id);
    if (!changed)
        return;
    item.words = words;
    item.quality = quality;
    item.error = error;
    item.time = time.isValid() ? time : QDateTime::currentDateTimeUtc();
    item.published = true;
    markDirty(index);
}

void MqttNorth::markDirty(std::size_t index)
{
    Item &item = m_items[index];
    if (item.dirty) {
        ++m_coalesced; // a newer state replaces one not yet encoded
        return;
    }
    item.dirty = true;
    m_dirty.push_back(index);
    if (!m_publishQueued) {
        m_publishQueued = true;
        QMetaObject::invokeMethod(this, &MqttNorth::publishDirty, Qt::QueuedConnection);
    }
}

void MqttNorth::publishDirty()
{
    // Once per batch of updates, and only while the broker connection takes more: beyond that the
    // items stay here, each with only its newest state, encoded when there is room (the oldest
    // change first). Under overload the gateway thus publishes fewer, newer values instead of
    // queueing every poll cycle (docs/performance.md).
    m_publishQueued = false;
    if (m_stopping)
        return;
    while (!m_dirty.empty() && m_publisher->hasRoom())
        publishNextDirty();
    if (!m_dirty.empty() && !m_publishRetry.isActive())
        m_publishRetry.start();
}

void MqttNorth::publishNextDirty()
{
    Item &item = m_items[m_dirty.front()];
    m_dirty.pop_front();
    item.dirty = false;
    publishItem(item);
}

void MqttNorth::publishItem(Item &item)
{
    m_delays.add(QDateTime::currentMSecsSinceEpoch() - item.time.toMSecsSinceEpoch());
    // A good item's payload starts the same for every value: written once.
    const bool good = item.quality == ValueQuality::Good;
    if (good && item.goodHead.isEmpty())
        item.goodHead = GatewayPayload::encodeItemHead(item.values, item.quality, {});
    const QByteArray head
        = good ? item.goodHead
               : GatewayPayload::encodeItemHead(item.values, item.quality, item.error);
    m_publisher->publishRetained(
        item.topicId, GatewayPayload::encodeItem(head, item.values, item.words, item.time));
}

void MqttNorth::updateSilence()
{
    // The link is up but no station answers (a stopped PLC, a wrong station number): no value of
    // this connection is current, and the status, the readers' gap marker, says so.
    const std::optional<Message> silence = m_activity.silence();
    if (silence && m_status == LinkStatus::Up) {
        m_silent = true;
        publishStatus(LinkStatus::Down, *silence);
    } else if (!silence && m_silent && m_status == LinkStatus::Down) {
        m_silent = false;
        publishStatus(LinkStatus::Up, {});
    }
}

void MqttNorth::plantLinkState(LinkState state, const Message &reason)
{
    if (m_stopping)
        return;
    // The link's own state wins; its stations start anew.
    m_activity.reset();
    m_silent = false;
    switch (state) {
    case LinkState::Connected:
        publishStatus(LinkStatus::Up, {});
        Q_EMIT logEvent(msg<MsgId::GatewayLogPlcLinkState>(linkStateMessage(state)));
        break;
    case LinkState::Lost: {
        publishStatus(LinkStatus::Down, reason);
        Q_EMIT logEvent(msg<MsgId::GatewayLogPlcLink>(linkStateMessage(state), reason));
        // Nothing stays good once the link is gone: the last value, marked stale, and why.
        const QDateTime now = QDateTime::currentDateTimeUtc();
        for (std::size_t i = 0; i < m_items.size(); ++i) {
            Item &item = m_items[i];
            // Stale for another reason (its station demoted): republished with the link's.
            if (item.quality == ValueQuality::Stale && item.published && item.error.id == reason.id)
                continue;
            item.quality = ValueQuality::Stale;
            item.error = reason;
            item.time = now;
            item.published = true;
            markDirty(i);
        }
        break;
    }
    case LinkState::Reconnecting:
    case LinkState::Connecting:
        // Until the first connection the status stays "connecting" (or "down" after a failed
        // attempt); later it stays "down" with the loss's reason until the link is up again.
        if (m_status == LinkStatus::Up)
            publishStatus(LinkStatus::Down, reason);
        break;
    case LinkState::Closed: break;
    }
}

void MqttNorth::publishStatus(LinkStatus state, const Message &reason)
{
    m_status = state;
    const GatewayPayload::Status status{state, m_linkText, reason, QDateTime::currentDateTimeUtc()};
    m_publisher->publishRetained(GatewayTopics::status(m_prefix, m_config.name),
                                 GatewayPayload::encodeStatus(status));
}

void MqttNorth::publishStatistics()
{
    m_publisher->publishRetained(GatewayTopics::statistics(m_prefix, m_config.name),
                                 GatewayStatistics::encode(statistics(), m_plant->statistics(),
                                                           m_linkText,
                                                           QDateTime::currentDateTimeUtc()));
    m_delays.clear(); // each statistics message covers its own interval
}

} // namespace Fatek
