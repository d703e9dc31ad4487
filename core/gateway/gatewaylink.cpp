#include "gatewaylink.h"

#include "core/mqtt/gatewaytopics.h"
#include "core/mqtt/mqttclient.h"
#include "core/mqtt/mqttmessages.h"
#include "core/protocol/logtext.h"
#include "core/session/changeverifier.h"
#include "core/session/session.h"
#include "gatewaymessages.h"
#include "gatewaypublisher.h"

namespace Fatek {

using GatewayPayload::LinkStatus;

namespace {

std::string addressString(const Address &address)
{
    return address.toString();
}

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

GatewayLink::GatewayLink(const GatewayConnectionConfig &config, const QString &prefix,
                         const MqttBrokerSettings &broker, bool readOnly, QObject *parent)
    : QObject(parent)
    , m_config(config)
    , m_prefix(prefix)
    , m_readOnly(readOnly)
    , m_linkText(config.link.toString())
    , m_session(new Session(config.link, this))
    , m_client(new MqttClient(persistentSession(broker, prefix, config.name), this))
    , m_publisher(new GatewayPublisher(m_client, this))
{
    registerSessionMetaTypes();
    // Core refuses writes too, should a command ever slip past the checks below.
    m_session->setReadOnly(readOnly);
    // Nothing reads a gateway link's traffic: its log would hold 10,000 frames per link for
    // nothing (about 7 MB for 200 items).
    m_session->trafficLog()->setCapacity(0);
    // The assembler's keys are the indexes into m_items.
    QList<WatchedItem> watched;
    for (const WatchTableSpec &table : m_config.tables) {
        for (const WatchItemSpec &spec : table.items) {
            Item item;
            item.values = ItemValues(spec);
            item.topic = GatewayTopics::item(prefix, config.name, spec.station, spec.address);
            item.topicId = m_publisher->retainedTopic(item.topic, 0);
            watched.append({m_items.size(), spec, table.intervalMs});
            m_itemOfTopic.insert(item.topic, m_items.size());
            m_items.push_back(std::move(item));
        }
    }
    m_assembler.setItems(watched);
    m_session->setWatchList(m_assembler.pollEntries());

    connect(m_session, &Session::values, this, &GatewayLink::onValues);
    connect(m_session, &Session::linkStateChanged, this, &GatewayLink::onLinkState);
    connect(m_client, &MqttClient::messageReceived, this, &GatewayLink::onCommand);
    connect(m_client, &MqttClient::connected, this, [this] {
        m_brokerDown = false;
        Q_EMIT logEvent(msg<MsgId::GatewayLogBrokerUp>(m_client->settings().toUrl().toStdString()));
    });
    connect(m_client, &MqttClient::disconnected, this, [this](const Message &reason) {
        if (!m_brokerDown) {
            m_brokerDown = true;
            m_brokerDownAt = QDateTime::currentDateTimeUtc();
        }
        if (!m_stopping)
            Q_EMIT logEvent(msg<MsgId::GatewayLogBrokerDown>(reason));
    });

    GatewayPayload::Status offline{LinkStatus::Offline, m_linkText, {}, {}};
    m_client->setWill(GatewayTopics::status(prefix, config.name),
                      GatewayPayload::encodeStatus(offline), 1, true);
    m_client->subscribe(GatewayTopics::setFilter(prefix, config.name), 1);

    m_statisticsTimer.setInterval(config.statisticsIntervalMs);
    connect(&m_statisticsTimer, &QTimer::timeout, this, &GatewayLink::publishStatistics);
    m_stopTimer.setInterval(20);
    connect(&m_stopTimer, &QTimer::timeout, this, &GatewayLink::checkStopped);
    m_publishRetry.setInterval(5);
    m_publishRetry.setSingleShot(true);
    connect(&m_publishRetry, &QTimer::timeout, this, &GatewayLink::publishDirty);
}

GatewayLink::~GatewayLink()
{
    // Signals of the children must not reach this half-destroyed object.
    disconnect(m_session, nullptr, this, nullptr);
    disconnect(m_client, nullptr, this, nullptr);
}

bool GatewayLink::start(Message *error, int pollDelayMs)
{
    if (!m_client->open()) {
        *error = m_client->openError();
        return false;
    }
    publishStatus(LinkStatus::Connecting, {});
    for (const HomeAssistantDiscovery::Entry &entry : m_discovery)
        m_publisher->publishRetained(entry.topic, entry.payload);
    if (pollDelayMs > 0) {
        QTimer::singleShot(pollDelayMs, this, [this] {
            if (!m_stopping)
                m_session->open();
        });
    } else {
        m_session->open();
    }
    m_statisticsTimer.start();
    return true;
}

void GatewayLink::setDiscovery(std::vector<HomeAssistantDiscovery::Entry> entries)
{
    m_discovery = std::move(entries);
}

void GatewayLink::clearDiscovery(const QSet<QString> &keep)
{
    for (const HomeAssistantDiscovery::Entry &entry : m_discovery) {
        if (!keep.contains(entry.topic))
            m_publisher->publishRetained(entry.topic, {});
    }
}

void GatewayLink::stop(int timeoutMs)
{
    if (m_stopping)
        return;
    m_stopping = true;
    m_statisticsTimer.stop();
    m_session->setWatchList({});
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

void GatewayLink::checkStopped()
{
    // Done when the broker took everything (outstanding 0: QoS 1 acknowledged), when there is no
    // broker to wait for, or at the bound.
    const bool delivered = m_publisher->waiting() == 0 && m_client->outstanding() == 0;
    if (m_stopped
        || (!delivered && m_client->isConnected() && !m_stopClock.hasExpired(m_stopTimeoutMs)))
        return;
    m_stopTimer.stop();
    m_client->close();
    m_session->close();
    m_stopped = true;
    Q_EMIT logEvent(msg<MsgId::GatewayLogStopped>());
    Q_EMIT stopped();
}

GatewayStatistics GatewayLink::statistics() const
{
    GatewayStatistics s = m_counters;
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

void GatewayLink::onValues(const QList<WatchValue> &values)
{
    if (m_stopping)
        return;
    // An item whose elements were never all read has no words: nothing invented goes out.
    for (const WatchItemValue &v : m_assembler.assemble(values))
        update(static_cast<std::size_t>(v.key), v.hasValue ? v.words : std::vector<std::uint32_t>{},
               v.quality, v.error, v.time);
}

void GatewayLink::update(std::size_t index, const std::vector<std::uint32_t> &words,
                         ValueQuality quality, const Message &error, const QDateTime &time)
{
    Item &item = m_items[index];
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

void GatewayLink::markDirty(std::size_t index)
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
        QMetaObject::invokeMethod(this, &GatewayLink::publishDirty, Qt::QueuedConnection);
    }
}

void GatewayLink::publishDirty()
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

void GatewayLink::publishNextDirty()
{
    Item &item = m_items[m_dirty.front()];
    m_dirty.pop_front();
    item.dirty = false;
    publishItem(item);
}

void GatewayLink::publishItem(Item &item)
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

void GatewayLink::onLinkState(LinkState state, const Message &reason)
{
    if (m_stopping)
        return;
    switch (state) {
    case LinkState::Connected:
        m_everUp = true;
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
            if (item.quality == ValueQuality::Stale && item.published)
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

void GatewayLink::publishStatus(LinkStatus state, const Message &reason)
{
    m_status = state;
    const GatewayPayload::Status status{state, m_linkText, reason, QDateTime::currentDateTimeUtc()};
    m_publisher->publishRetained(GatewayTopics::status(m_prefix, m_config.name),
                                 GatewayPayload::encodeStatus(status));
}

void GatewayLink::publishStatistics()
{
    m_publisher->publishRetained(GatewayTopics::statistics(m_prefix, m_config.name),
                                 GatewayStatistics::encode(statistics(), m_session->statistics(),
                                                           m_linkText,
                                                           QDateTime::currentDateTimeUtc()));
    m_delays.clear(); // each statistics message covers its own interval
}

void GatewayLink::answer(const GatewayPayload::Reply &reply)
{
    m_publisher->publishReply(
        GatewayTopics::itemReply(m_prefix, m_config.name, reply.station, reply.address),
        GatewayPayload::encodeReply(reply));
    Q_EMIT logEvent(msg<MsgId::GatewayLogWrite>(
        reply.station, addressString(reply.address), reply.value.toStdString(),
        reply.id.toStdString(),
        reply.ok && reply.error.empty() ? msg<MsgId::GatewayWriteDone>() : reply.error));
}

void GatewayLink::refuse(GatewayPayload::Reply reply, const Message &why)
{
    ++m_counters.writesRefused;
    reply.ok = false;
    reply.error = why;
    reply.time = QDateTime::currentDateTimeUtc();
    answer(reply);
}

Message GatewayLink::tooOld(const GatewayPayload::SetCommand &command, bool queued) const
{
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const qint64 maxMs = qint64(m_config.commandMaxAgeSec) * 1000;
    const auto seconds = [](qint64 ms) {
        return QString::number(static_cast<double>(ms) / 1000.0, 'f', 1).toStdString();
    };
    if (command.time) {
        const qint64 age = command.time->msecsTo(now);
        if (age < -qint64(MaxAheadSec) * 1000)
            return msg<MsgId::GatewayWriteFuture>(seconds(-age), MaxAheadSec);
        if (age > maxMs)
            return msg<MsgId::GatewayWriteExpired>(seconds(age), m_config.commandMaxAgeSec);
    }
    if (!queued)
        return {}; // came straight through: as old as the broker's hand-over
    // Kept by the broker while this gateway was away: at most as old as the outage. Checked with
    // a "time" too: that is the sender's word, the outage the gateway's own measure.
    if (!m_brokerDownAt.isValid()) {
        // Away since this program started: only the command's time tells its age.
        return command.time ? Message{}
                            : msg<MsgId::GatewayWriteAgeUnknown>(m_config.commandMaxAgeSec);
    }
    const qint64 waited = m_brokerDownAt.msecsTo(now);
    return waited > maxMs
               ? msg<MsgId::GatewayWriteWaited>(seconds(waited), m_config.commandMaxAgeSec)
               : Message{};
}

void GatewayLink::onCommand(const QString &topic, const QByteArray &payload, bool retained,
                            bool queued)
{
    const std::optional<GatewayTopics::Parsed> parsed = GatewayTopics::parse(m_prefix, topic);
    if (m_stopping)
        return;
    if (!parsed) {
        // <prefix>/<connection>/<station>/<address>/set with levels that name no item: the
        // sender waits on the matching reply topic, so it is answered there.
        const QStringList levels = topic.mid(m_prefix.size() + 1).split(u'/');
        if (topic.startsWith(m_prefix + u'/') && levels.size() == 4 && levels[0] == m_config.name
            && levels[3] == u"set") {
            ++m_counters.writesRefused;
            GatewayPayload::Reply reply;
            reply.stationLevel = levels[1];
            reply.addressLevel = levels[2];
            reply.error = msg<MsgId::GatewayNoSuchItem>(escapedForLog(levels[1].toStdString()),
                                                        escapedForLog(levels[2].toStdString()));
            reply.time = QDateTime::currentDateTimeUtc();
            m_publisher->publishReply(topic.left(topic.size() - 3) + QStringLiteral("reply"),
                                      GatewayPayload::encodeReply(reply));
            Q_EMIT logEvent(msg<MsgId::GatewayWriteBadTopic>(topic.toStdString()));
            return;
        }
    }
    if (!parsed || parsed->kind != GatewayTopics::Kind::Set
        || parsed->connection != m_config.name) {
        // Nowhere to answer: only counted and logged.
        ++m_counters.writesRefused;
        Q_EMIT logEvent(msg<MsgId::GatewayWriteBadTopic>(topic.toStdString()));
        return;
    }
    // The broker sends a retained command again at every subscription, also right after it
    // handed over the same command queued for this session (issue 48: two replies to one
    // command). A retained copy of the last command on its topic was answered already.
    if (retained && m_lastCommand.value(topic) == payload)
        return;
    if (m_lastCommand.size() >= MaxRememberedCommands)
        m_lastCommand.clear();
    m_lastCommand.insert(topic, payload);
    GatewayPayload::Reply reply;
    reply.station = parsed->station;
    reply.address = parsed->address;
    if (payload.size() > MaxCommandBytes)
        return refuse(reply, msg<MsgId::GatewayWriteTooLong>(MaxCommandBytes));
    Message decodeError;
    const std::optional<GatewayPayload::SetCommand> command
        = GatewayPayload::decodeSet(payload, &decodeError);
    if (command) {
        reply.id = command->id;
        reply.value = command->value;
    }
    if (retained)
        return refuse(reply, msg<MsgId::GatewayWriteRetained>());
    if (!command)
        return refuse(reply, decodeError);
    if (m_readOnly)
        return refuse(reply, msg<MsgId::GatewayWriteReadOnly>());
    if (Message old = tooOld(*command, queued); !old.empty())
        return refuse(reply, old);

    // The item's spec: the command's format, else the watched item's at this address, else the
    // address's default (as a new row of a watch table gets). allowNonFinite: the watched item's.
    WatchItemSpec spec;
    spec.address = parsed->address;
    spec.station = static_cast<quint8>(parsed->station);
    spec.format = ValueFormat::defaultFormat(parsed->address);
    const auto watched = m_itemOfTopic.constFind(
        GatewayTopics::item(m_prefix, m_config.name, parsed->station, parsed->address));
    if (watched != m_itemOfTopic.cend()) {
        spec.format = m_items[*watched].values.item().format;
        spec.swapWords = m_items[*watched].values.item().swapWords;
        // NaN and infinities only where the watch list allows them for this item.
        spec.allowNonFinite = m_items[*watched].values.item().allowNonFinite;
    }
    if (command->format)
        spec.format = *command->format;
    if (command->swapWords)
        spec.swapWords = *command->swapWords;
    if (const Status valid = WatchList::validateEntry(spec); !valid)
        return refuse(reply, valid.error().message);
    const ItemValues item(spec);
    for (int i = 0; i < item.elementCount(); ++i) {
        const Address element = item.elementAddress(i);
        if (!m_config.allows(element))
            return refuse(reply, msg<MsgId::GatewayWriteNotAllowed>(addressString(element)));
    }
    Result<std::uint64_t> raw = std::uint64_t(0);
    if (command->words) {
        // The raw value itself (the studio's writes): one word per element, nothing parsed.
        if (std::ssize(*command->words) != item.elementCount())
            return refuse(reply, msg<MsgId::GatewaySetWordCount>(
                                     static_cast<int>(command->words->size()),
                                     addressString(spec.address), item.elementCount()));
        // Each word must fit its element (join() would cut 70000 to 4464, 2 on a bit to OFF).
        raw = item.fromWords(*command->words);
        if (raw)
            reply.value = item.text(*raw); // for the reply and the log, as the PLC gets it
    } else {
        raw = item.parse(command->value);
    }
    if (!raw)
        return refuse(reply, raw.error().message);
    if (m_pendingWrites >= MaxPendingWrites)
        return refuse(reply, msg<MsgId::GatewayWriteBusy>(m_pendingWrites));

    ++m_counters.writesAccepted;
    ++m_pendingWrites;
    // Not sent once the command is older than its age limit: a write that waited behind a dead
    // PLC must not land when its sender has given up on it (it was told "unknown" or "expired").
    RequestOptions options;
    options.deadline.setRemainingTime(std::max<qint64>(0, qint64(m_config.commandMaxAgeSec) * 1000
                                                              - commandAgeMs(*command, queued)));
    ChangeVerifier::submit(
        m_session, item.writeRequest(*raw), this,
        [this, reply](const ChangeReport &report) {
            if (report.final)
                --m_pendingWrites;
            GatewayPayload::Reply done = reply;
            done.ok = report.outcome == ChangeOutcome::Done;
            done.outcome = report.outcome;
            done.final = report.final;
            done.error = report.message;
            done.time = QDateTime::currentDateTimeUtc();
            if (report.final && report.outcome == ChangeOutcome::Refused)
                ++m_counters.writesFailed;
            if (report.final && report.outcome == ChangeOutcome::Unknown)
                ++m_counters.writesUnknown;
            answer(done);
        },
        options);
}

qint64 GatewayLink::commandAgeMs(const GatewayPayload::SetCommand &command, bool queued) const
{
    // The older of its own time (tooOld refused one in the future) and, for a command the broker
    // kept, the time since this gateway lost the broker; a live command without a time came now.
    const QDateTime now = QDateTime::currentDateTimeUtc();
    qint64 age = command.time ? command.time->msecsTo(now) : 0;
    if (queued && m_brokerDownAt.isValid())
        age = std::max(age, m_brokerDownAt.msecsTo(now));
    return std::max<qint64>(0, age);
}

} // namespace Fatek
