#include "alarmpayload.h"

#include "core/mqtt/messagejson.h"
#include "core/mqtt/mqttmessages.h"
#include "core/watch/jsonkeys.h"
#include "gatewaymessages.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QStringList>

#include <cmath>

namespace Fatek {

namespace {

QJsonValue timeOrNull(qint64 ms)
{
    return ms > 0 ? QJsonValue(AlarmPayload::timeText(ms)) : QJsonValue(QJsonValue::Null);
}

// What a state and an event both say about the alarm.
void insertAlarm(QJsonObject &object, const AlarmStatus &status)
{
    object.insert(QStringLiteral("id"), status.alarmId);
    object.insert(QStringLiteral("state"), Alarms::stateName(status.state));
    object.insert(QStringLiteral("priority"), Alarms::priorityName(status.definition.priority));
    object.insert(QStringLiteral("kind"), Alarms::kindName(status.definition.kind));
    if (Alarms::isLimitKind(status.definition.kind))
        object.insert(QStringLiteral("limit"), status.definition.limit);
    object.insert(QStringLiteral("message"), status.message);
    object.insert(QStringLiteral("group"), status.definition.group);
    object.insert(QStringLiteral("item"), status.itemName);
    object.insert(QStringLiteral("address"), status.address);
    object.insert(QStringLiteral("station"), status.station);
}

QStringList keysOf(GatewayTopics::AlarmAction action)
{
    QStringList keys{QStringLiteral("id"), QStringLiteral("time"), QStringLiteral("user")};
    if (action != GatewayTopics::AlarmAction::Unshelve)
        keys << QStringLiteral("comment");
    if (action == GatewayTopics::AlarmAction::Shelve)
        keys << QStringLiteral("until") << QStringLiteral("durationSec");
    return keys;
}

// An ISO 8601 time with its offset (without one the sender's zone would be a guess).
std::optional<QDateTime> timeWithOffset(const QJsonValue &value)
{
    const QDateTime time = QDateTime::fromString(value.toString(), Qt::ISODateWithMs);
    if (!value.isString() || !time.isValid() || time.timeSpec() == Qt::LocalTime)
        return std::nullopt;
    return time;
}

} // namespace

QString AlarmPayload::timeText(qint64 msSinceEpoch)
{
    const QDateTime local = QDateTime::fromMSecsSinceEpoch(msSinceEpoch);
    return local.toOffsetFromUtc(local.offsetFromUtc()).toString(Qt::ISODateWithMs);
}

QByteArray AlarmPayload::encodeState(const AlarmStatus &status, qint64 nowMs)
{
    QJsonObject object;
    insertAlarm(object, status);
    object.insert(QStringLiteral("value"), status.value);
    object.insert(QStringLiteral("conditionActive"), status.conditionActive);
    object.insert(QStringLiteral("chattering"), status.chattering);
    object.insert(QStringLiteral("since"), timeOrNull(status.sinceMs));
    object.insert(QStringLiteral("raised"), timeOrNull(status.raisedMs));
    object.insert(QStringLiteral("shelvedUntil"),
                  timeOrNull(status.state == AlarmState::Shelved ? status.shelvedUntilMs : 0));
    object.insert(QStringLiteral("user"), status.lastUser);
    object.insert(QStringLiteral("comment"), status.lastComment);
    object.insert(QStringLiteral("time"), timeText(nowMs));
    return QJsonDocument(object).toJson(QJsonDocument::Compact);
}

QByteArray AlarmPayload::encodeEvent(const AlarmEvent &event,
                                     const std::optional<AlarmStatus> &status)
{
    QJsonObject object;
    if (status)
        insertAlarm(object, *status);
    // The event's own fields win over the alarm's present ones.
    object.insert(QStringLiteral("id"), event.alarmId);
    object.insert(QStringLiteral("event"), Alarms::eventName(event.type));
    object.insert(QStringLiteral("state"), Alarms::stateName(event.state));
    object.insert(QStringLiteral("priority"), Alarms::priorityName(event.priority));
    object.insert(QStringLiteral("kind"), Alarms::kindName(event.kind));
    object.insert(QStringLiteral("message"), event.message);
    object.insert(QStringLiteral("group"), event.group);
    object.insert(QStringLiteral("value"), event.value);
    object.insert(QStringLiteral("user"), event.user);
    object.insert(QStringLiteral("comment"), event.comment);
    object.insert(QStringLiteral("shelvedUntil"), timeOrNull(event.shelvedUntilMs));
    object.insert(QStringLiteral("time"), timeText(event.timeMs));
    return QJsonDocument(object).toJson(QJsonDocument::Compact);
}

std::optional<AlarmPayload::Command> AlarmPayload::decodeCommand(const QByteArray &payload,
                                                                 GatewayTopics::AlarmAction action,
                                                                 Message *error)
{
    Command command;
    const QByteArray trimmed = payload.trimmed();
    const bool shelve = action == GatewayTopics::AlarmAction::Shelve;
    if (!trimmed.startsWith('{')) {
        // Plain text (a button's fixed payload) says nothing more; a shelve needs its expiry.
        if (!shelve)
            return command;
        *error = msg<MsgId::GatewayAlarmBadShelve>(MaxShelveSec);
        return std::nullopt;
    }
    QJsonParseError parseError{};
    const QJsonDocument document = QJsonDocument::fromJson(trimmed, &parseError);
    if (parseError.error != QJsonParseError::NoError || !document.isObject()) {
        *error = msg<MsgId::GatewaySetNotJson>();
        return std::nullopt;
    }
    if (std::optional<Message> twice = JsonKeys::firstDuplicate(trimmed)) {
        *error = std::move(*twice);
        return std::nullopt;
    }
    const QJsonObject object = document.object();
    const QStringList known = keysOf(action);
    for (const QString &key : object.keys()) {
        if (!known.contains(key)) {
            *error = msg<MsgId::GatewayAlarmUnknownKey>(
                key.left(40).toStdString(), known.join(QStringLiteral(", ")).toStdString());
            return std::nullopt;
        }
    }
    const QJsonValue id = object.value(QStringLiteral("id"));
    if (id.isDouble())
        command.id = QString::number(id.toDouble(), 'g', QLocale::FloatingPointShortest);
    else if (id.isString())
        command.id = id.toString();
    else if (!id.isUndefined()) {
        *error = msg<MsgId::GatewaySetBadId>();
        return std::nullopt;
    }
    if (object.contains(QStringLiteral("time"))) {
        command.time = timeWithOffset(object.value(QStringLiteral("time")));
        if (!command.time) {
            *error = msg<MsgId::GatewaySetBadTime>(
                object.value(QStringLiteral("time")).toString().left(40).toStdString());
            return std::nullopt;
        }
    }
    for (const auto &[key, target] : {std::pair{QStringLiteral("user"), &command.user},
                                      std::pair{QStringLiteral("comment"), &command.comment}}) {
        const QJsonValue value = object.value(key);
        if (value.isUndefined())
            continue;
        if (!value.isString()) {
            *error = msg<MsgId::GatewayAlarmNotText>(key.toStdString());
            return std::nullopt;
        }
        *target = value.toString();
    }
    if (!shelve)
        return command;
    const QJsonValue until = object.value(QStringLiteral("until"));
    const QJsonValue duration = object.value(QStringLiteral("durationSec"));
    if (!until.isUndefined() && duration.isUndefined())
        command.until = timeWithOffset(until);
    const double seconds = duration.toDouble(-1);
    if (until.isUndefined() && duration.isDouble() && seconds >= 1
        && seconds <= static_cast<double>(MaxShelveSec) && seconds == std::floor(seconds))
        command.durationMs = static_cast<qint64>(seconds) * 1000;
    if (!command.until && !command.durationMs) {
        *error = msg<MsgId::GatewayAlarmBadShelve>(MaxShelveSec);
        return std::nullopt;
    }
    return command;
}

QByteArray AlarmPayload::encodeReply(const Reply &reply)
{
    QJsonObject object{
        {QStringLiteral("id"), reply.id},
        {QStringLiteral("ok"), reply.ok},
        {QStringLiteral("action"), GatewayTopics::alarmActionLevel(reply.action)},
        {QStringLiteral("alarm"), reply.alarmId},
        {QStringLiteral("time"), timeText(reply.timeMs)},
    };
    if (reply.state)
        object.insert(QStringLiteral("state"), Alarms::stateName(*reply.state));
    if (!reply.error.empty())
        object.insert(QStringLiteral("error"), MessageJson::toJson(reply.error));
    return QJsonDocument(object).toJson(QJsonDocument::Compact);
}

} // namespace Fatek
