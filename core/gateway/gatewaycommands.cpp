#include "gatewaycommands.h"

#include "commandage.h"
#include "core/mqtt/gatewaytopics.h"
#include "core/mqtt/mqttclient.h"
#include "core/mqtt/mqttmessages.h"
#include "core/plant/plantconnection.h"
#include "core/protocol/logtext.h"
#include "gatewaymessages.h"
#include "gatewaypublisher.h"

#include <algorithm>
#include <utility>

namespace Fatek {

GatewayCommands::GatewayCommands(const GatewayConnectionConfig &config, const QString &prefix,
                                 bool readOnly, WatchedAt watched, MqttClient *client,
                                 GatewayPublisher *publisher, PlantConnection *plant,
                                 QObject *parent)
    : QObject(parent)
    , m_config(config)
    , m_prefix(prefix)
    , m_readOnly(readOnly)
    , m_watched(std::move(watched))
    , m_publisher(publisher)
    , m_plant(plant)
{
    connect(client, &MqttClient::messageReceived, this, &GatewayCommands::onCommand);
    connect(client, &MqttClient::connected, this, [this] { m_brokerDown = false; });
    connect(client, &MqttClient::disconnected, this, [this] {
        if (!m_brokerDown) {
            m_brokerDown = true;
            m_brokerDownAt = QDateTime::currentDateTimeUtc();
        }
    });
    client->subscribe(GatewayTopics::setFilter(prefix, config.name), 1);
}

void GatewayCommands::answer(const GatewayPayload::Reply &reply)
{
    m_publisher->publishReply(
        GatewayTopics::itemReply(m_prefix, m_config.name, reply.station, reply.address),
        GatewayPayload::encodeReply(reply));
    // The sender's value and id between quotes: their own quotes escaped (issue 55).
    Q_EMIT logEvent(msg<MsgId::GatewayLogWrite>(
        reply.station, reply.address.toString(), quotedFieldForLog(reply.value.toStdString()),
        quotedFieldForLog(reply.id.toStdString()),
        reply.ok && reply.error.empty() ? msg<MsgId::GatewayWriteDone>() : reply.error));
}

void GatewayCommands::refuse(GatewayPayload::Reply reply, const Message &why)
{
    ++m_counters.refused;
    reply.ok = false;
    reply.error = why;
    reply.time = QDateTime::currentDateTimeUtc();
    answer(reply);
}

Message GatewayCommands::tooOld(const GatewayPayload::SetCommand &command, bool queued) const
{
    return CommandAge::tooOld(command.time, queued, m_brokerDownAt, m_config.commandMaxAgeSec);
}

qint64 GatewayCommands::commandAgeMs(const GatewayPayload::SetCommand &command, bool queued) const
{
    return CommandAge::ageMs(command.time, queued, m_brokerDownAt);
}

bool GatewayCommands::refuseBadTopic(const QString &topic)
{
    // <prefix>/<connection>/<station>/<address>/set with levels that name no item: the sender
    // waits on the matching reply topic, so it is answered there.
    const QStringList levels = topic.mid(m_prefix.size() + 1).split(u'/');
    ++m_counters.refused;
    if (topic.startsWith(m_prefix + u'/') && levels.size() == 4 && levels[0] == m_config.name
        && levels[3] == u"set") {
        GatewayPayload::Reply reply;
        reply.stationLevel = levels[1];
        reply.addressLevel = levels[2];
        reply.error = msg<MsgId::GatewayNoSuchItem>(escapedForLog(levels[1].toStdString()),
                                                    escapedForLog(levels[2].toStdString()));
        reply.time = QDateTime::currentDateTimeUtc();
        m_publisher->publishReply(topic.left(topic.size() - 3) + QStringLiteral("reply"),
                                  GatewayPayload::encodeReply(reply));
        // Logged as what its sender was told: refused, and why.
        Q_EMIT logEvent(msg<MsgId::GatewayLogBadTopicRefused>(
            quotedFieldForLog(topic.toStdString()), reply.error));
        return true;
    }
    // Anything else has nowhere to be answered: only counted and logged.
    Q_EMIT logEvent(msg<MsgId::GatewayWriteBadTopic>(topic.toStdString()));
    return true;
}

WatchItemSpec GatewayCommands::specOf(int station, const Address &address,
                                      const GatewayPayload::SetCommand &command) const
{
    // The command's format, else the watched item's at this address, else the address's default
    // (as a new row of a watch table gets). allowNonFinite: the watched item's.
    WatchItemSpec spec;
    spec.address = address;
    spec.station = static_cast<quint8>(station);
    spec.format = ValueFormat::defaultFormat(address);
    if (const WatchItemSpec *watched
        = m_watched(GatewayTopics::item(m_prefix, m_config.name, station, address))) {
        spec.format = watched->format;
        spec.swapWords = watched->swapWords;
        // NaN and infinities only where the watch list allows them for this item.
        spec.allowNonFinite = watched->allowNonFinite;
    }
    if (command.format)
        spec.format = *command.format;
    if (command.swapWords)
        spec.swapWords = *command.swapWords;
    return spec;
}

void GatewayCommands::onCommand(const QString &topic, const QByteArray &payload, bool retained,
                                bool queued)
{
    if (m_stopping)
        return;
    // The alarm commands of this connection come on the same broker connection: AlarmNorth's.
    if (GatewayTopics::parseAlarmCommand(m_prefix, topic))
        return;
    const std::optional<GatewayTopics::Parsed> parsed = GatewayTopics::parse(m_prefix, topic);
    if (!parsed || parsed->kind != GatewayTopics::Kind::Set
        || parsed->connection != m_config.name) {
        refuseBadTopic(topic);
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
        // A words command's value is its words as sent ([0,16712]) until they are converted:
        // its refusals show them (issue 55: they were logged as "").
        if (command->words) {
            QStringList words;
            for (const std::uint32_t word : *command->words)
                words << QString::number(word);
            reply.value = u'[' + words.join(u',') + u']';
        }
    }
    if (retained)
        return refuse(reply, msg<MsgId::GatewayWriteRetained>());
    if (!command)
        return refuse(reply, decodeError);
    if (m_readOnly)
        return refuse(reply, msg<MsgId::GatewayWriteReadOnly>());
    if (Message old = tooOld(*command, queued); !old.empty())
        return refuse(reply, old);

    const WatchItemSpec spec = specOf(parsed->station, parsed->address, *command);
    if (const Status valid = WatchList::validateEntry(spec); !valid)
        return refuse(reply, valid.error().message);
    const ItemValues item(spec);
    for (int i = 0; i < item.elementCount(); ++i) {
        const Address element = item.elementAddress(i);
        if (!m_config.allows(element))
            return refuse(reply, msg<MsgId::GatewayWriteNotAllowed>(element.toString()));
    }
    Result<std::uint64_t> raw = std::uint64_t(0);
    if (command->words) {
        // The raw value itself (the studio's writes): one word per element, nothing parsed.
        if (std::ssize(*command->words) != item.elementCount())
            return refuse(reply, msg<MsgId::GatewaySetWordCount>(
                                     static_cast<int>(command->words->size()),
                                     spec.address.toString(), item.elementCount()));
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
    write(reply, item, *raw,
          std::max<qint64>(0, qint64(m_config.commandMaxAgeSec) * 1000
                                  - commandAgeMs(*command, queued)));
}

void GatewayCommands::write(const GatewayPayload::Reply &reply, const ItemValues &item,
                            std::uint64_t raw, qint64 remainingMs)
{
    ++m_counters.accepted;
    ++m_pendingWrites;
    // Not sent once the command is older than its age limit: a write that waited behind a dead
    // PLC must not land when its sender has given up on it (it was told "unknown" or "expired").
    m_plant->write(item.item(), raw, QDeadlineTimer(remainingMs), this,
                   [this, reply](const LinkWriteResult &result) {
                       if (result.final)
                           --m_pendingWrites;
                       GatewayPayload::Reply done = reply;
                       done.ok = result.outcome == ChangeOutcome::Done;
                       done.outcome = result.outcome;
                       done.final = result.final;
                       done.error = result.error;
                       done.time = QDateTime::currentDateTimeUtc();
                       if (result.final && result.outcome == ChangeOutcome::Refused)
                           ++m_counters.failed;
                       if (result.final && result.outcome == ChangeOutcome::Unknown)
                           ++m_counters.unknown;
                       answer(done);
                   });
}

} // namespace Fatek
