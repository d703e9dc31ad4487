#pragma once

#include "core/watch/alarmdefinition.h"

#include <QDateTime>
#include <QMetaType>
#include <QString>

#include <cstdint>

namespace Fatek {

// The states of ISA-18.2 (IEC 62682), one at a time.
enum class AlarmState {
    Normal,          // condition clear, nothing to acknowledge
    ActiveUnacked,   // condition present, not acknowledged (the summary flashes it)
    ActiveAcked,     // condition present, acknowledged
    ReturnedUnacked, // condition cleared before it was acknowledged
    Shelved,         // hidden by an operator until an expiry; the condition is still followed
    OutOfService,    // disabled by design (the definition's "enabled": false)
};

// What happened to an alarm: every one is journaled.
enum class AlarmEventType {
    Raised,       // the condition came (after its on-delay)
    Returned,     // the condition went (after its off-delay)
    Acknowledged, // by an operator
    Shelved,      // by an operator, until a time
    Unshelved,    // by an operator or at its expiry
    OutOfService, // its definition was disabled
    InService,    // its definition was enabled again
};

namespace Alarms {
// "normal", "activeUnacked", "activeAcked", "returnedUnacked", "shelved", "outOfService".
QString stateName(AlarmState state);
std::optional<AlarmState> stateFromName(const QString &name);
// "raised", "returned", "acknowledged", "shelved", "unshelved", "outOfService", "inService".
QString eventName(AlarmEventType type);
std::optional<AlarmEventType> eventFromName(const QString &name);
// Whether the state is one the operator must still act on (active or returned unacknowledged).
inline bool isUnacked(AlarmState s)
{
    return s == AlarmState::ActiveUnacked || s == AlarmState::ReturnedUnacked;
}
// Whether the summary lists it (every state but Normal).
inline bool isListed(AlarmState s)
{
    return s != AlarmState::Normal;
}
// Raises within ChatterWindowMs that make an alarm chattering (ISA-18.2's rule of thumb: three
// in a minute).
inline constexpr int ChatterCount = 3;
inline constexpr qint64 ChatterWindowMs = 60000;
} // namespace Alarms

// What an alarm's state machine keeps across a restart (the journal's "states" table): enough to
// bring an alarm back active and unacknowledged if it was so.
struct AlarmRecord
{
    QString connection;
    QString alarmId;
    AlarmState state = AlarmState::Normal;
    qint64 sinceMs = 0;           // when it entered `state` (ms since the epoch, UTC)
    qint64 raisedMs = 0;          // when it was last raised (0: never)
    qint64 shelvedUntilMs = 0;    // while Shelved
    bool conditionActive = false; // whether its condition was present when last known

    bool operator==(const AlarmRecord &) const = default;
};

// One event of one alarm, as the journal keeps it and the gateway publishes it.
struct AlarmEvent
{
    qint64 timeMs = 0;  // ms since the epoch, UTC
    int utcOffsetS = 0; // the local offset at that time (the journal shows local time with it)
    QString connection;
    QString alarmId;
    AlarmEventType type = AlarmEventType::Raised;
    AlarmState state = AlarmState::Normal; // after the event
    AlarmKind kind = AlarmKind::High;
    AlarmPriority priority = AlarmPriority::Medium;
    QString message;
    QString group;
    QString value;   // the item's value as text when it happened (empty for operator actions)
    QString user;    // who acknowledged or shelved (operator name or OS user)
    QString comment; // the operator's comment
    qint64 shelvedUntilMs = 0; // for Shelved

    bool operator==(const AlarmEvent &) const = default;
};

// One alarm as a summary or a status topic shows it.
struct AlarmStatus
{
    QString connection;
    QString alarmId;
    AlarmDefinition definition;
    QString itemName; // name, else address
    QString address;  // "R100"
    quint8 station = 1;
    QString message;
    AlarmState state = AlarmState::Normal;
    bool conditionActive = false;
    bool chattering = false;
    qint64 sinceMs = 0;  // entered `state`
    qint64 raisedMs = 0; // last raised (0: never)
    qint64 shelvedUntilMs = 0;
    QString value; // the item's last value as text
    QString lastUser;
    QString lastComment;
};

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::AlarmEvent)
Q_DECLARE_METATYPE(Fatek::AlarmStatus)
Q_DECLARE_METATYPE(Fatek::AlarmRecord)
