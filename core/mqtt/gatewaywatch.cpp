#include "gatewaywatch.h"

#include "core/session/session.h"
#include "gatewaytopics.h"
#include "mqttclient.h"

#include <QThread>
#include <QUuid>

#include <algorithm>

namespace Fatek {

namespace {

std::string utf8(const QString &text)
{
    return text.toStdString();
}

std::string describe(int station, const Address &address, const QString &text)
{
    return address.toString() + " (station " + std::to_string(station) + ") = " + utf8(text);
}

} // namespace

Message GatewayWatchSettings::validate() const
{
    if (!GatewayTopics::isValidPrefix(prefix))
        return msg<MsgId::GatewayPrefixInvalid>(utf8(prefix));
    if (!GatewayTopics::isValidConnectionName(connection))
        return msg<MsgId::GatewayNameInvalid>(utf8(connection));
    return broker.validate();
}

GatewayWatch::GatewayWatch(const GatewayWatchSettings &settings, QObject *parent)
    : QObject(parent)
    , m_settings(settings)
    , m_client(new MqttClient(settings.broker, this))
{
    registerSessionMetaTypes();
    m_client->subscribe(GatewayTopics::status(settings.prefix, settings.connection), 1);
    m_client->subscribe(GatewayTopics::itemFilter(settings.prefix, settings.connection), 0);
    m_client->subscribe(GatewayTopics::itemFilter(settings.prefix, settings.connection)
                            + QStringLiteral("/reply"),
                        1);
    connect(m_client, &MqttClient::connected, this, &GatewayWatch::onConnected);
    connect(m_client, &MqttClient::disconnected, this, &GatewayWatch::onDisconnected);
    connect(m_client, &MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload) { onMessage(topic, payload); });
    m_graceTimer.setSingleShot(true);
    connect(&m_graceTimer, &QTimer::timeout, this, [this] {
        m_settled = true;
        markAllDirty();
    });
    // A burst of retained items (hundreds after a subscribe) becomes one batch.
    m_flushTimer.setSingleShot(true);
    m_flushTimer.setInterval(20);
    connect(&m_flushTimer, &QTimer::timeout, this, &GatewayWatch::flush);
}

GatewayWatch::~GatewayWatch()
{
    // The client's thread may still deliver; nothing may reach a half-destroyed object.
    disconnect(m_client, nullptr, this, nullptr);
}

void GatewayWatch::open()
{
    if (m_state != LinkState::Closed)
        return;
    if (!m_client->open()) {
        setState(LinkState::Lost, m_client->openError());
        return;
    }
    setState(LinkState::Connecting, {});
}

void GatewayWatch::close()
{
    m_client->close();
    m_brokerUp = false;
    m_status.reset();
    m_graceTimer.stop();
    setState(LinkState::Closed, {});
    // Unanswered writes end now: nobody will read their replies.
    const QStringList ids = m_writes.keys();
    for (const QString &id : ids) {
        GatewayPayload::Reply reply = m_writes.value(id).request;
        reply.error = msg<MsgId::GatewayWriteNotSent>(
            describe(reply.station, reply.address, reply.value),
            msg<MsgId::MqttClosed>(utf8(m_settings.broker.toUrl())));
        finishWrite(id, reply);
    }
}

void GatewayWatch::onConnected()
{
    m_brokerUp = true;
    // What the broker retains now is the truth: items and status come again after the subscribe.
    m_elements.clear();
    m_itemElements.clear();
    m_status.reset();
    m_settled = false;
    setState(LinkState::Connecting, msg<MsgId::GatewayNoStatus>(utf8(m_settings.connection)));
}

void GatewayWatch::onDisconnected(const Message &reason)
{
    m_brokerUp = false;
    m_status.reset();
    m_graceTimer.stop();
    if (m_state != LinkState::Closed)
        setState(LinkState::Lost, reason);
}

void GatewayWatch::setState(LinkState state, const Message &reason)
{
    if (state == m_state && reason == m_reason)
        return;
    m_state = state;
    m_reason = reason;
    // Every value's quality follows the link: stale with the reason, or the payload's again.
    markAllDirty();
    Q_EMIT linkStateChanged(state, reason);
}

void GatewayWatch::onMessage(const QString &topic, const QByteArray &payload)
{
    const std::optional<GatewayTopics::Parsed> parsed
        = GatewayTopics::parse(m_settings.prefix, topic);
    if (!parsed || parsed->connection != m_settings.connection)
        return;
    switch (parsed->kind) {
    case GatewayTopics::Kind::Item: onItem(topic, payload); break;
    case GatewayTopics::Kind::Status: onStatus(payload); break;
    case GatewayTopics::Kind::Reply: onReply(payload); break;
    case GatewayTopics::Kind::Set:
    case GatewayTopics::Kind::Statistics: break;
    }
}

void GatewayWatch::onItem(const QString &topic, const QByteArray &payload)
{
    QStringList keys;
    // An empty payload removes a retained item (the gateway stopped publishing it); garbage from
    // another program on our topic counts as nothing published.
    if (const std::optional<GatewayPayload::ItemValue> item = GatewayPayload::decodeItem(payload)) {
        for (std::size_t n = 0; n < item->words.size(); ++n) {
            const QString key
                = keyOf(item->station, item->address.advanced(static_cast<std::uint32_t>(n)));
            Element &element = m_elements[key];
            element.value = item->words[n];
            element.quality = item->quality;
            element.time = item->time;
            element.error = item->quality == ValueQuality::Good ? Message{} : item->error;
            keys << key;
            markDirty(key);
        }
    }
    const QStringList previous = m_itemElements.value(topic);
    for (const QString &key : previous) {
        if (!keys.contains(key)) {
            m_elements.remove(key);
            markDirty(key);
        }
    }
    if (keys.isEmpty())
        m_itemElements.remove(topic);
    else
        m_itemElements.insert(topic, keys);
}

void GatewayWatch::onStatus(const QByteArray &payload)
{
    if (!m_brokerUp)
        return;
    const std::optional<GatewayPayload::Status> status = GatewayPayload::decodeStatus(payload);
    m_status = status;
    const std::string name = utf8(m_settings.connection);
    if (!status) {
        setState(LinkState::Connecting, msg<MsgId::GatewayNoStatus>(name));
        return;
    }
    m_gatewayLink = status->link;
    switch (status->state) {
    case GatewayPayload::LinkStatus::Up:
        // The gateway publishes its items right after its status: from here they are on their
        // way, and the grace is how long they may take.
        if (!m_settled && !m_graceTimer.isActive())
            m_graceTimer.start(m_graceMs);
        setState(LinkState::Connected, {});
        break;
    case GatewayPayload::LinkStatus::Connecting:
        setState(LinkState::Connecting, msg<MsgId::GatewayConnecting>(name));
        break;
    case GatewayPayload::LinkStatus::Down:
        setState(LinkState::Lost, status->reason.empty()
                                      ? msg<MsgId::GatewayDown>(name)
                                      : msg<MsgId::GatewayDownBecause>(name, status->reason));
        break;
    case GatewayPayload::LinkStatus::Offline:
        setState(LinkState::Lost, status->reason.empty()
                                      ? msg<MsgId::GatewayOffline>(name)
                                      : msg<MsgId::GatewayOfflineBecause>(name, status->reason));
        break;
    }
}

void GatewayWatch::onReply(const QByteArray &payload)
{
    std::optional<GatewayPayload::Reply> reply = GatewayPayload::decodeReply(payload);
    if (!reply || !m_writes.contains(reply->id))
        return; // another client's write
    if (!reply->ok && reply->error.empty())
        reply->error = msg<MsgId::GatewayWriteFailed>(utf8(m_settings.connection));
    finishWrite(reply->id, *reply);
}

void GatewayWatch::setWatchList(const QList<WatchEntry> &entries)
{
    m_entries = entries;
    m_entriesOf.clear();
    for (int i = 0; i < m_entries.size(); ++i)
        m_entriesOf[keyOf(m_entries.at(i).station, m_entries.at(i).address)].append(i);
    m_dirty.clear();
    markAllDirty();
}

QString GatewayWatch::keyOf(int station, const Address &address)
{
    return QString::number(station) + u'/' + QString::fromStdString(address.toString());
}

void GatewayWatch::markDirty(const QString &elementKey)
{
    const auto it = m_entriesOf.constFind(elementKey);
    if (it == m_entriesOf.cend())
        return;
    m_dirty += it.value();
    m_flushTimer.start();
}

void GatewayWatch::markAllDirty()
{
    m_allDirty = true;
    m_flushTimer.start();
}

WatchValue GatewayWatch::valueOf(const WatchEntry &entry) const
{
    WatchValue value;
    value.itemId = entry.id;
    const auto element = m_elements.constFind(keyOf(entry.station, entry.address));
    const bool covered = element != m_elements.cend();
    if (covered) {
        value.value = element->value;
        value.timestamp = element->time;
    }
    if (m_state != LinkState::Connected) {
        // Whatever the payload said, it is not fresh while the gateway or the broker is away.
        value.quality = ValueQuality::Stale;
        value.error = m_reason.empty() ? linkStateMessage(m_state) : m_reason;
    } else if (covered) {
        value.quality = element->quality;
        value.error = element->error;
    } else {
        value.quality = ValueQuality::Error;
        value.error = msg<MsgId::GatewayNotPublished>(entry.address.toString(), int(entry.station),
                                                      utf8(m_settings.connection));
    }
    return value;
}

void GatewayWatch::flush()
{
    QList<int> indexes;
    if (m_allDirty) {
        indexes.reserve(m_entries.size());
        for (int i = 0; i < m_entries.size(); ++i)
            indexes << i;
    } else {
        std::sort(m_dirty.begin(), m_dirty.end());
        indexes = m_dirty;
        indexes.erase(std::unique(indexes.begin(), indexes.end()), indexes.end());
    }
    m_allDirty = false;
    m_dirty.clear();
    QList<WatchValue> batch;
    for (int i : std::as_const(indexes)) {
        const WatchEntry &entry = m_entries.at(i);
        // Until the retained items had time to come, a missing one is not yet "not published".
        const bool pending = m_state == LinkState::Connected && !m_settled
                             && !m_elements.contains(keyOf(entry.station, entry.address));
        if (!pending)
            batch << valueOf(entry);
    }
    if (!batch.isEmpty())
        Q_EMIT values(batch);
}

void GatewayWatch::write(int station, const Address &address, const QString &text,
                         DisplayFormat format, bool swapWords, QObject *context,
                         WriteCompletion completion)
{
    const QString id = QUuid::createUuid().toString(QUuid::WithoutBraces);
    PendingWrite pending;
    pending.context = context;
    pending.hasContext = context != nullptr;
    pending.completion = std::move(completion);
    pending.request.id = id;
    pending.request.station = station;
    pending.request.address = address;
    pending.request.value = text;
    m_writes.insert(id, pending);

    const std::string what = describe(station, address, text);
    Message refusal;
    // Enforced here, whatever the buttons show: operator mode changes nothing in any PLC.
    if (m_readOnly)
        refusal = msg<MsgId::SessionReadOnly>(what);
    else if (!m_brokerUp || !m_status || m_status->state == GatewayPayload::LinkStatus::Offline)
        refusal = msg<MsgId::GatewayWriteNotSent>(what, m_reason.empty() ? linkStateMessage(m_state)
                                                                         : m_reason);
    if (refusal.empty()) {
        GatewayPayload::SetCommand command;
        command.value = text;
        command.format = format;
        command.swapWords = swapWords;
        command.id = id;
        const QString topic
            = GatewayTopics::itemSet(m_settings.prefix, m_settings.connection, station, address);
        if (!m_client->publish(topic, GatewayPayload::encodeSet(command), 1, false))
            refusal = msg<MsgId::GatewayPublishFailed>(utf8(m_settings.broker.toUrl()));
    }
    if (!refusal.empty()) {
        GatewayPayload::Reply reply = pending.request;
        reply.error = refusal;
        // Like a reply, never inside the caller's call.
        QMetaObject::invokeMethod(
            this, [this, id, reply] { finishWrite(id, reply); }, Qt::QueuedConnection);
        return;
    }
    QTimer::singleShot(m_replyTimeoutMs, this, [this, id] {
        if (!m_writes.contains(id))
            return;
        GatewayPayload::Reply reply = m_writes.value(id).request;
        reply.error = msg<MsgId::GatewayNoReply>(utf8(m_settings.connection),
                                                 (m_replyTimeoutMs + 999) / 1000);
        finishWrite(id, reply);
    });
}

void GatewayWatch::finishWrite(const QString &id, const GatewayPayload::Reply &reply)
{
    const auto it = m_writes.find(id);
    if (it == m_writes.end())
        return;
    const PendingWrite pending = it.value();
    m_writes.erase(it);
    if (pending.hasContext && !pending.context)
        return; // the asker is gone
    if (!pending.completion)
        return;
    if (!pending.hasContext || pending.context->thread() == QThread::currentThread())
        pending.completion(reply);
    else
        QMetaObject::invokeMethod(
            pending.context.data(), [completion = pending.completion, reply] { completion(reply); },
            Qt::QueuedConnection);
}

} // namespace Fatek
