#include "gatewaywatch.h"

#include "core/mqtt/gatewaytopics.h"
#include "core/mqtt/mqttclient.h"
#include "core/mqtt/mqttmessages.h"
#include "core/session/session.h"
#include "linkmessages.h"

#include <QThread>
#include <QUuid>

#include <algorithm>

namespace Fatek {

namespace {

std::string utf8(const QString &text)
{
    return text.toStdString();
}

std::string describe(const WatchItemSpec &item, const QString &text)
{
    return item.address.toString() + " (station " + std::to_string(item.station)
           + ") = " + utf8(text);
}

} // namespace

GatewayWatch::GatewayWatch(const GatewayWatchSettings &settings, QObject *parent)
    : PlcLink(parent)
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

void GatewayWatch::close(CloseMode)
{
    m_client->close();
    m_brokerUp = false;
    m_status.reset();
    m_graceTimer.stop();
    setState(LinkState::Closed, {});
    // Unanswered writes end now: nobody will read their replies. The broker took each command,
    // so the gateway may still carry it out: unknown, not failed.
    const QStringList ids = m_writes.keys();
    for (const QString &id : ids) {
        finishWrite(id, {false,
                         msg<MsgId::GatewayWriteUnanswered>(
                             m_writes.value(id).what,
                             msg<MsgId::MqttClosed>(utf8(m_settings.broker.toUrl()))),
                         ChangeOutcome::Unknown, true});
    }
}

void GatewayWatch::reconnectNow()
{
    if (m_state == LinkState::Connected || m_state == LinkState::Connecting)
        return;
    close();
    open();
}

void GatewayWatch::onConnected()
{
    m_brokerUp = true;
    // What the broker retains now is the truth: items and status come again after the subscribe.
    m_published.clear();
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
    case GatewayTopics::Kind::Item: onItem(parsed->station, parsed->address, payload); break;
    case GatewayTopics::Kind::Status: onStatus(payload); break;
    case GatewayTopics::Kind::Reply: onReply(payload); break;
    case GatewayTopics::Kind::Set:
    case GatewayTopics::Kind::Statistics: break;
    }
}

void GatewayWatch::onItem(int station, const Address &address, const QByteArray &payload)
{
    const QString key = keyOf(station, address);
    // An empty payload removes a retained item (the gateway stopped publishing it); garbage from
    // another program on our topic counts as nothing published.
    if (const std::optional<GatewayPayload::ItemValue> item = GatewayPayload::decodeItem(payload)) {
        Published &published = m_published[key];
        published.words = item->words;
        published.quality = item->quality;
        published.time = item->time;
        published.name = item->name;
        published.error = item->quality == ValueQuality::Good ? Message{} : item->error;
    } else if (!m_published.remove(key)) {
        return;
    }
    markDirty(key);
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
    finishWrite(reply->id, {reply->ok, reply->error, reply->outcome, reply->final});
}

void GatewayWatch::setItems(const QList<WatchedItem> &items)
{
    m_items.clear();
    m_itemsAt.clear();
    for (const WatchedItem &item : items) {
        const QString key = keyOf(item.spec.station, item.spec.address);
        m_itemsAt[key].append(static_cast<int>(m_items.size()));
        m_items.push_back({item, ItemValues(item.spec), key});
    }
    m_dirty.clear();
    markAllDirty();
}

QString GatewayWatch::keyOf(int station, const Address &address)
{
    return QString::number(station) + u'/' + QString::fromStdString(address.toString());
}

void GatewayWatch::markDirty(const QString &key)
{
    const auto it = m_itemsAt.constFind(key);
    if (it == m_itemsAt.cend())
        return;
    m_dirty += it.value();
    m_flushTimer.start();
}

void GatewayWatch::markAllDirty()
{
    m_allDirty = true;
    m_flushTimer.start();
}

WatchItemValue GatewayWatch::valueOf(const Watched &watched) const
{
    WatchItemValue value;
    value.key = watched.item.key;
    const auto count = static_cast<std::size_t>(watched.values.elementCount());
    value.words.assign(count, 0);
    const auto published = m_published.constFind(watched.key);
    std::size_t covered = 0;
    if (published != m_published.cend()) {
        // The gateway's item there, as it is: its words are the elements' (element 0 first).
        covered = std::min(count, published->words.size());
        std::copy_n(published->words.cbegin(), covered, value.words.begin());
        value.raw = watched.values.join(value.words);
        value.time = published->time;
        value.hasValue = covered == count;
        value.name = published->name;
    }
    if (m_state != LinkState::Connected) {
        // Whatever the payload said, it is not fresh while the gateway or the broker is away.
        value.quality = ValueQuality::Stale;
        value.error = m_reason.empty() ? linkStateMessage(m_state) : m_reason;
    } else if (value.hasValue) {
        value.quality = published->quality;
        value.error = published->error;
    } else if (published != m_published.cend() && published->words.empty()) {
        // The gateway has the item but never read it (its PLC link was never up).
        value.quality
            = published->quality == ValueQuality::Good ? ValueQuality::Stale : published->quality;
        value.error = published->error;
    } else {
        // Nothing there, or an item over fewer elements (R100 published as one word, watched
        // as a float): the first element it lacks is not published.
        const WatchItemSpec &spec = watched.item.spec;
        value.quality = ValueQuality::Error;
        value.error = msg<MsgId::GatewayNotPublished>(
            spec.address.advanced(static_cast<std::uint32_t>(covered)).toString(),
            int(spec.station), utf8(m_settings.connection));
    }
    return value;
}

void GatewayWatch::flush()
{
    QList<int> indexes;
    if (m_allDirty) {
        indexes.reserve(static_cast<qsizetype>(m_items.size()));
        for (int i = 0; i < static_cast<int>(m_items.size()); ++i)
            indexes << i;
    } else {
        std::sort(m_dirty.begin(), m_dirty.end());
        indexes = m_dirty;
        indexes.erase(std::unique(indexes.begin(), indexes.end()), indexes.end());
    }
    m_allDirty = false;
    m_dirty.clear();
    QList<WatchItemValue> batch;
    for (int i : std::as_const(indexes)) {
        const Watched &watched = m_items[static_cast<std::size_t>(i)];
        // Until the retained items had time to come, a missing one is not yet "not published".
        const bool pending
            = m_state == LinkState::Connected && !m_settled && !m_published.contains(watched.key);
        if (!pending)
            batch << valueOf(watched);
    }
    if (!batch.isEmpty())
        Q_EMIT itemValues(batch);
}

void GatewayWatch::writeItem(const WatchItemSpec &item, std::uint64_t raw,
                             const std::optional<QDeadlineTimer> &deadline, QObject *context,
                             WriteCompletion completion)
{
    Q_UNUSED(deadline);
    const QString id = QUuid::createUuid().toString(QUuid::WithoutBraces);
    const ItemValues values(item);
    PendingWrite pending;
    pending.context = context;
    pending.hasContext = context != nullptr;
    pending.completion = std::move(completion);
    pending.what = describe(item, values.text(raw));
    m_writes.insert(id, pending);

    Message refusal;
    // Enforced here, whatever the buttons show: operator mode changes nothing in any PLC.
    if (m_readOnly)
        refusal = msg<MsgId::SessionReadOnly>(pending.what);
    else if (!m_brokerUp || !m_status || m_status->state == GatewayPayload::LinkStatus::Offline)
        refusal = msg<MsgId::GatewayWriteNotSent>(
            pending.what, m_reason.empty() ? linkStateMessage(m_state) : m_reason);
    if (refusal.empty()) {
        // The typed value itself, not its text: the gateway writes these words as they are.
        GatewayPayload::SetCommand command;
        command.words = values.split(raw);
        command.format = item.format;
        command.swapWords = item.swapWords;
        command.id = id;
        command.time = QDateTime::currentDateTimeUtc(); // a late delivery is refused, not done
        const QString topic = GatewayTopics::itemSet(m_settings.prefix, m_settings.connection,
                                                     item.station, item.address);
        if (!m_client->publish(topic, GatewayPayload::encodeSet(command), 1, false))
            refusal = msg<MsgId::GatewayPublishFailed>(utf8(m_settings.broker.toUrl()));
    }
    if (!refusal.empty()) {
        // Like a reply, never inside the caller's call.
        QMetaObject::invokeMethod(
            this,
            [this, id, refusal] {
                finishWrite(id, {false, refusal});
            },
            Qt::QueuedConnection);
        return;
    }
    // No reply in time: the gateway may still carry it out, so the outcome is unknown, and the
    // final word is its reply if one comes (or the close of this link).
    QTimer::singleShot(m_replyTimeoutMs, this, [this, id] {
        if (m_writes.contains(id) && !m_writes.value(id).reported)
            finishWrite(id, {false,
                             msg<MsgId::GatewayNoReply>(utf8(m_settings.connection),
                                                        (m_replyTimeoutMs + 999) / 1000),
                             ChangeOutcome::Unknown, false});
    });
}

void GatewayWatch::finishWrite(const QString &id, const LinkWriteResult &result)
{
    const auto it = m_writes.find(id);
    if (it == m_writes.end())
        return;
    const PendingWrite pending = it.value();
    if (result.final || (pending.hasContext && !pending.context))
        m_writes.erase(it);
    else
        it->reported = true; // an unknown outcome so far: the final reply is still awaited
    if (pending.hasContext && !pending.context)
        return; // the asker is gone
    if (!pending.completion)
        return;
    if (!pending.hasContext || pending.context->thread() == QThread::currentThread())
        pending.completion(result);
    else
        QMetaObject::invokeMethod(
            pending.context.data(),
            [completion = pending.completion, result] { completion(result); },
            Qt::QueuedConnection);
}

} // namespace Fatek
