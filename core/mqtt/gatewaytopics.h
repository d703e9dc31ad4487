#pragma once

#include "core/protocol/address.h"

#include <QString>

#include <cstdint>
#include <optional>

namespace Fatek {

// The gateway's topic scheme, the one place that builds and reads topics:
//   <prefix>/<connection>/<station>/<address>          item value (retained), e.g.
//   fatek/line1/1/R100 <prefix>/<connection>/<station>/<address>/set      write command (to the
//   gateway) <prefix>/<connection>/<station>/<address>/reply    the gateway's answer to a command
//   <prefix>/<connection>/status                       link status (retained; will "offline")
//   <prefix>/<connection>/statistics                   link counters (retained, every few seconds)
//   <prefix>/<connection>/alarms/<alarm id>           an alarm's state (retained)
//   <prefix>/<connection>/alarms/events                every alarm event (not retained)
//   <prefix>/<connection>/alarms/<alarm id>/ack        acknowledge (also /shelve, /unshelve)
//   <prefix>/<connection>/alarms/<alarm id>/reply      the gateway's answer to an alarm command
// The prefix may have several levels ("plant/fatek"). Addresses are in the short form users type
// ("R100", "DR10", "Y0"), so a topic reads like the watch table.
namespace GatewayTopics {

// A connection name usable as one topic level: 1..64 characters, letters, digits, '-', '_', '.',
// and not a number (the station level is one).
bool isValidConnectionName(const QString &name);
// A prefix: one or more non-empty levels without '+', '#' or NUL, not starting with '$' or '/',
// not ending with '/'.
bool isValidPrefix(const QString &prefix);

QString item(const QString &prefix, const QString &connection, int station, const Address &address);
QString itemSet(const QString &prefix, const QString &connection, int station,
                const Address &address);
QString itemReply(const QString &prefix, const QString &connection, int station,
                  const Address &address);
QString status(const QString &prefix, const QString &connection);
QString statistics(const QString &prefix, const QString &connection);
// Subscriptions: every item of a connection, every write command of a connection.
QString itemFilter(const QString &prefix, const QString &connection);
QString setFilter(const QString &prefix, const QString &connection);

// Alarms (issue 50). Alarm ids ("1-R100-high") never say "events".
QString alarm(const QString &prefix, const QString &connection, const QString &alarmId);
QString alarmEvents(const QString &prefix, const QString &connection);
QString alarmReply(const QString &prefix, const QString &connection, const QString &alarmId);
// An operator's action on an alarm, the last level of its command topic.
enum class AlarmAction { Acknowledge, Shelve, Unshelve };
QString alarmActionLevel(AlarmAction action); // "ack", "shelve", "unshelve"
QString alarmCommand(const QString &prefix, const QString &connection, const QString &alarmId,
                     AlarmAction action);
// One subscription per action: a filter of every level under the alarm would also bring back
// the gateway's own replies.
QString alarmCommandFilter(const QString &prefix, const QString &connection, AlarmAction action);
struct AlarmCommandTopic
{
    QString connection;
    QString alarmId;
    AlarmAction action = AlarmAction::Acknowledge;
};
// A command topic of an alarm; nullopt for any other topic.
std::optional<AlarmCommandTopic> parseAlarmCommand(const QString &prefix, const QString &topic);

enum class Kind { Item, Set, Reply, Status, Statistics };

struct Parsed
{
    Kind kind = Kind::Item;
    QString connection;
    int station = 0; // items, sets and replies
    Address address; // items, sets and replies
};

// What a topic under `prefix` is; nullopt for anything else (another prefix, a bad address).
std::optional<Parsed> parse(const QString &prefix, const QString &topic);

} // namespace GatewayTopics

} // namespace Fatek
