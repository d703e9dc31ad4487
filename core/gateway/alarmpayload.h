#pragma once

#include "core/alarm/alarmtypes.h"
#include "core/mqtt/gatewaytopics.h"
#include "core/protocol/message.h"

#include <QByteArray>
#include <QDateTime>
#include <QString>

#include <optional>

namespace Fatek {

// The gateway's alarm payloads (issue 50; docs/gateway.md, "Alarms"), the one place that writes
// and reads them. Times are ISO 8601 in the gateway's local time with its UTC offset, as the
// journal shows them ("2026-11-27T18:15:00.000+08:00"); a time that is not set is null.
namespace AlarmPayload {

// An alarm's state, retained on <prefix>/<conn>/alarms/<id>:
//   {"id":"1-R100-high","state":"activeUnacked","priority":"high","kind":"high","limit":1000,
//    "message":"...","group":"...","item":"Tank level","address":"R100","station":1,
//    "value":"1500","conditionActive":true,"chattering":false,"since":"...","raised":"...",
//    "shelvedUntil":null,"user":"...","comment":"...","time":"..."}
// "value" is the item's value at the alarm's last event; "user" and "comment" those of the last
// operator action; "time" when this payload was made.
QByteArray encodeState(const AlarmStatus &status, qint64 nowMs);

// One event, on <prefix>/<conn>/alarms/events (not retained): the state fields of its alarm and
//   {"event":"raised","state":"activeUnacked","value":"1500","user":"","comment":"",
//    "shelvedUntil":null,"time":"..."}
QByteArray encodeEvent(const AlarmEvent &event, const std::optional<AlarmStatus> &status);

// An operator's command on <alarm>/ack, /shelve or /unshelve: empty or plain text (a Home
// Assistant button's "PRESS": no id, user or comment), or a JSON object with the keys of its
// action only (a misspelt "coment" is refused, not dropped):
//   ack       {"id":"a1","time":"...","user":"anna","comment":"valve closed"}
//   shelve    {..., "until":"2026-11-27T20:00:00+08:00"} or {..., "durationSec":3600}
//   unshelve  {"id":"a1","time":"...","user":"anna"}
struct Command
{
    QString id;
    std::optional<QDateTime> time;
    QString user;
    QString comment;
    std::optional<QDateTime> until;   // shelve
    std::optional<qint64> durationMs; // shelve
};
// Longest shelve taken ("durationSec"; an "until" further ahead too): a week.
inline constexpr qint64 MaxShelveSec = 7 * 24 * 3600;
// nullopt: refused, `error` says why (also for a shelve with neither "until" nor "durationSec").
std::optional<Command> decodeCommand(const QByteArray &payload, GatewayTopics::AlarmAction action,
                                     Message *error);

// The answer on <alarm>/reply: {"id":"a1","ok":true,"action":"ack","alarm":"1-R100-high",
// "state":"activeAcked","time":"..."}, or "ok":false with "error" (a message as JSON).
struct Reply
{
    QString id;
    bool ok = false;
    GatewayTopics::AlarmAction action = GatewayTopics::AlarmAction::Acknowledge;
    QString alarmId;
    std::optional<AlarmState> state; // after the command, when the alarm exists
    Message error;
    qint64 timeMs = 0;
};
QByteArray encodeReply(const Reply &reply);

// The time as the payloads write it (local, with the UTC offset).
QString timeText(qint64 msSinceEpoch);

} // namespace AlarmPayload

} // namespace Fatek
