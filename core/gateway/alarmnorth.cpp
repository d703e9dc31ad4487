#include "alarmnorth.h"

#include "commandage.h"
#include "core/alarm/alarmengine.h"
#include "core/mqtt/mqttclient.h"
#include "core/mqtt/mqttmessages.h"
#include "core/plant/plantconnection.h" // AlarmEngine::plant()'s QPointer needs the whole type
#include "core/protocol/logtext.h"
#include "gatewaymessages.h"
#include "gatewaypublisher.h"

namespace Fatek {

namespace {

constexpr GatewayTopics::AlarmAction Actions[]
    = {GatewayTopics::AlarmAction::Acknowledge, GatewayTopics::AlarmAction::Shelve,
       GatewayTopics::AlarmAction::Unshelve};

std::string text(const QString &s)
{
    return s.toStdString();
}

} // namespace

AlarmNorth::AlarmNorth(const GatewayConnectionConfig &config, const QString &prefix,
                       AlarmEngine *engine, MqttClient *client, GatewayPublisher *publisher,
                       QObject *parent)
    : QObject(parent)
    , m_config(config)
    , m_prefix(prefix)
    , m_engine(engine)
    , m_publisher(publisher)
{
    connect(engine, &AlarmEngine::alarmEvent, this, &AlarmNorth::onEvent);
    connect(engine, &AlarmEngine::alarmsReset, this, &AlarmNorth::onReset);
    connect(client, &MqttClient::messageReceived, this, &AlarmNorth::onMessage);
    connect(client, &MqttClient::connected, this, [this] { m_brokerDown = false; });
    connect(client, &MqttClient::disconnected, this, [this] {
        if (!m_brokerDown) {
            m_brokerDown = true;
            m_brokerDownAt = QDateTime::currentDateTimeUtc();
        }
    });
    // A connection without alarms takes no alarm commands (none could be carried out).
    if (engine->alarmCount() > 0) {
        for (const GatewayTopics::AlarmAction action : Actions)
            client->subscribe(GatewayTopics::alarmCommandFilter(prefix, config.name, action), 1);
    }
}

QSet<QString> AlarmNorth::stateTopics(const QString &prefix,
                                      const GatewayConnectionConfig &connection)
{
    QSet<QString> topics;
    for (const WatchTableSpec &table : connection.tables) {
        for (const WatchItemSpec &spec : table.items) {
            for (const AlarmDefinition &alarm : spec.alarms)
                topics.insert(GatewayTopics::alarm(prefix, connection.name,
                                                   Alarms::alarmId(spec, alarm.kind)));
        }
    }
    return topics;
}

void AlarmNorth::start()
{
    m_started = true;
    if (!m_awaitRestore)
        publishAll();
}

void AlarmNorth::onReset()
{
    m_awaitRestore = false;
    publishAll();
}

void AlarmNorth::clearStates(const QSet<QString> &keep)
{
    for (const QString &alarmId : std::as_const(m_published)) {
        const QString topic = GatewayTopics::alarm(m_prefix, m_config.name, alarmId);
        if (!keep.contains(topic))
            m_publisher->publishRetained(topic, {});
    }
}

void AlarmNorth::publishAll()
{
    if (!m_started || m_stopping || !m_engine)
        return;
    // Alarms the engine no longer has (its items were replaced) leave the broker too.
    QSet<QString> now;
    for (const AlarmStatus &status : m_engine->alarms())
        now.insert(status.alarmId);
    for (const QString &alarmId : std::as_const(m_published)) {
        if (!now.contains(alarmId))
            m_publisher->publishRetained(GatewayTopics::alarm(m_prefix, m_config.name, alarmId),
                                         {});
    }
    m_published.clear();
    for (const QString &alarmId : std::as_const(now))
        publishState(alarmId);
}

void AlarmNorth::publishState(const QString &alarmId)
{
    const std::optional<AlarmStatus> status = m_engine->status(alarmId);
    if (!status)
        return;
    m_published.insert(alarmId);
    m_publisher->publishRetained(
        GatewayTopics::alarm(m_prefix, m_config.name, alarmId),
        AlarmPayload::encodeState(*status, QDateTime::currentMSecsSinceEpoch()));
}

void AlarmNorth::onEvent(const AlarmEvent &event, const AlarmRecord &)
{
    if (!m_started || m_stopping || !m_engine)
        return;
    const std::optional<AlarmStatus> status = m_engine->status(event.alarmId);
    // Not retained, QoS 1, bounded like the replies: a reader that was away reads the states.
    m_publisher->publishReply(GatewayTopics::alarmEvents(m_prefix, m_config.name),
                              AlarmPayload::encodeEvent(event, status));
    publishState(event.alarmId);
    const std::string id = text(event.alarmId);
    switch (event.type) {
    case AlarmEventType::Raised:
        Q_EMIT logEvent(
            msg<MsgId::GatewayLogAlarmRaised>(id, text(Alarms::priorityName(event.priority)),
                                              text(event.message), text(event.value)));
        break;
    case AlarmEventType::Returned:
        Q_EMIT logEvent(
            msg<MsgId::GatewayLogAlarmReturned>(id, text(event.message), text(event.value)));
        break;
    case AlarmEventType::Acknowledged:
    case AlarmEventType::Shelved:
    case AlarmEventType::Unshelved:
        if (!event.user.isEmpty()) {
            Q_EMIT logEvent(msg<MsgId::GatewayLogAlarmAction>(
                id, text(Alarms::eventName(event.type)), text(event.user),
                quotedFieldForLog(text(event.comment))));
            break;
        }
        [[fallthrough]]; // an unshelve at the shelve's expiry: nobody did it
    case AlarmEventType::OutOfService:
    case AlarmEventType::InService:
        Q_EMIT logEvent(msg<MsgId::GatewayLogAlarmEvent>(id, text(Alarms::eventName(event.type))));
        break;
    }
}

void AlarmNorth::onMessage(const QString &topic, const QByteArray &payload, bool retained,
                           bool queued)
{
    if (m_stopping || !m_engine)
        return;
    const std::optional<GatewayTopics::AlarmCommandTopic> target
        = GatewayTopics::parseAlarmCommand(m_prefix, topic);
    if (!target || target->connection != m_config.name)
        return; // GatewayCommands' (write commands and strays)
    // The broker sends a retained command again at every subscription, also right after it
    // handed over the same command queued for this session: that copy was answered already.
    if (retained && m_lastCommand.value(topic) == payload)
        return;
    if (m_lastCommand.size() >= MaxRememberedCommands)
        m_lastCommand.clear();
    m_lastCommand.insert(topic, payload);
    AlarmPayload::Reply reply;
    reply.action = target->action;
    reply.alarmId = target->alarmId;
    Message error = retained ? msg<MsgId::GatewayAlarmRetained>() : Message{};
    if (payload.size() > MaxCommandBytes)
        error = msg<MsgId::GatewayWriteTooLong>(MaxCommandBytes);
    if (error.empty())
        error = carryOut(*target, payload, queued, reply);
    reply.ok = error.empty();
    reply.error = error;
    if (const std::optional<AlarmStatus> status = m_engine->status(target->alarmId))
        reply.state = status->state;
    reply.timeMs = QDateTime::currentMSecsSinceEpoch();
    answer(reply);
}

Message AlarmNorth::carryOut(const GatewayTopics::AlarmCommandTopic &target,
                             const QByteArray &payload, bool queued, AlarmPayload::Reply &reply)
{
    Message error;
    const std::optional<AlarmPayload::Command> command
        = AlarmPayload::decodeCommand(payload, target.action, &error);
    if (!command)
        return error;
    reply.id = command->id;
    if (Message old
        = CommandAge::tooOld(command->time, queued, m_brokerDownAt, m_config.commandMaxAgeSec);
        !old.empty())
        return old;
    if (!m_engine->status(target.alarmId))
        return msg<MsgId::GatewayAlarmUnknown>(text(target.alarmId));
    const QString user = command->user.isEmpty() ? DefaultUser : command->user;
    Status done = Ok{};
    switch (target.action) {
    case GatewayTopics::AlarmAction::Acknowledge:
        done = m_engine->acknowledge(target.alarmId, user, command->comment);
        break;
    case GatewayTopics::AlarmAction::Shelve: {
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        const qint64 until
            = command->until ? command->until->toMSecsSinceEpoch() : now + *command->durationMs;
        if (until > now + AlarmPayload::MaxShelveSec * 1000)
            return msg<MsgId::GatewayAlarmBadShelve>(AlarmPayload::MaxShelveSec);
        done = m_engine->shelve(target.alarmId, until, user, command->comment);
        break;
    }
    case GatewayTopics::AlarmAction::Unshelve:
        done = m_engine->unshelve(target.alarmId, user);
        break;
    }
    return done ? Message{} : done.error().message;
}

void AlarmNorth::answer(const AlarmPayload::Reply &reply)
{
    m_publisher->publishReply(GatewayTopics::alarmReply(m_prefix, m_config.name, reply.alarmId),
                              AlarmPayload::encodeReply(reply));
    if (!reply.ok)
        Q_EMIT logEvent(msg<MsgId::GatewayLogAlarmRefused>(
            text(reply.alarmId), text(GatewayTopics::alarmActionLevel(reply.action)),
            quotedFieldForLog(text(reply.id)), reply.error));
}

} // namespace Fatek
