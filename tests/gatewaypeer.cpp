#include "gatewaypeer.h"

#include "core/mqtt/gatewaytopics.h"
#include "core/mqtt/mqttclient.h"
#include "core/watch/itemvalues.h"

#include <QDateTime>

#include <algorithm>

using namespace Fatek;

namespace TestUtil {

GatewayPeer::GatewayPeer(const MqttBrokerSettings &broker, const QString &prefix,
                         const QString &connection, QObject *parent)
    : QObject(parent)
    , m_prefix(prefix)
    , m_connection(connection)
    , m_client(new MqttClient(broker, this))
{
    m_status.state = GatewayPayload::LinkStatus::Up;
    m_status.link = QStringLiteral("TCP 127.0.0.1:500, FACON");
    GatewayPayload::Status will;
    will.state = GatewayPayload::LinkStatus::Offline;
    m_client->setWill(GatewayTopics::status(prefix, connection),
                      GatewayPayload::encodeStatus(will));
    m_client->subscribe(GatewayTopics::setFilter(prefix, connection), 1);
    connect(m_client, &MqttClient::connected, this, &GatewayPeer::publishAll);
    connect(m_client, &MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload) { onMessage(topic, payload); });
}

GatewayPeer::~GatewayPeer()
{
    disconnect(m_client, nullptr, this, nullptr);
}

bool GatewayPeer::open()
{
    return m_client->open();
}

bool GatewayPeer::isConnected() const
{
    return m_client->isConnected();
}

void GatewayPeer::setItem(const WatchItemSpec &spec, const std::vector<std::uint32_t> &words,
                          ValueQuality quality, const Message &error)
{
    const Item item{spec, words, quality, error};
    auto it = std::find_if(m_items.begin(), m_items.end(), [&](const Item &i) {
        return i.spec.station == spec.station && i.spec.address == spec.address;
    });
    if (it != m_items.end())
        *it = item;
    else
        m_items.append(item);
    publishItem(item);
}

void GatewayPeer::setStatus(GatewayPayload::LinkStatus state, const Message &reason)
{
    m_status.state = state;
    m_status.reason = reason;
    m_status.time = QDateTime::currentDateTimeUtc();
    m_client->publish(GatewayTopics::status(m_prefix, m_connection),
                      GatewayPayload::encodeStatus(m_status), 1, true);
}

void GatewayPeer::publishAll()
{
    m_status.time = QDateTime::currentDateTimeUtc();
    m_client->publish(GatewayTopics::status(m_prefix, m_connection),
                      GatewayPayload::encodeStatus(m_status), 1, true);
    for (const Item &item : std::as_const(m_items))
        publishItem(item);
}

void GatewayPeer::publishItem(const Item &item)
{
    m_client->publish(
        GatewayTopics::item(m_prefix, m_connection, item.spec.station, item.spec.address),
        GatewayPayload::encodeItem(ItemValues(item.spec), item.words, item.quality,
                                   QDateTime::currentDateTimeUtc(), item.error),
        1, true);
}

void GatewayPeer::onMessage(const QString &topic, const QByteArray &payload)
{
    const std::optional<GatewayTopics::Parsed> parsed = GatewayTopics::parse(m_prefix, topic);
    if (!parsed || parsed->kind != GatewayTopics::Kind::Set)
        return;
    ++m_setCount;
    Message error;
    const std::optional<GatewayPayload::SetCommand> command
        = GatewayPayload::decodeSet(payload, &error);
    if (!command)
        return;
    m_commands.append(*command);
    if (!m_answering)
        return;
    GatewayPayload::Reply reply;
    reply.id = command->id;
    reply.station = parsed->station;
    reply.address = parsed->address;
    reply.value = command->value;
    reply.time = QDateTime::currentDateTimeUtc();
    reply.ok = m_refusal.empty();
    reply.error = m_refusal;
    if (reply.ok) {
        // The gateway writes the PLC, and the next poll publishes the new value.
        auto it = std::find_if(m_items.begin(), m_items.end(), [&](const Item &i) {
            return i.spec.station == parsed->station && i.spec.address == parsed->address;
        });
        if (it != m_items.end()) {
            WatchItemSpec spec = it->spec;
            if (command->format)
                spec.format = *command->format;
            if (command->swapWords)
                spec.swapWords = *command->swapWords;
            const ItemValues values(spec);
            if (command->words) {
                it->words = *command->words; // the raw value as sent
                publishItem(*it);
            } else if (const Result<std::uint64_t> raw = values.parse(command->value)) {
                it->words = values.split(*raw);
                publishItem(*it);
            }
        }
    }
    m_client->publish(
        GatewayTopics::itemReply(m_prefix, m_connection, parsed->station, parsed->address),
        GatewayPayload::encodeReply(reply), 1, false);
}

} // namespace TestUtil
