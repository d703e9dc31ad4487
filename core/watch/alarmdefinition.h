#pragma once

#include "core/protocol/result.h"

#include <QJsonValue>
#include <QList>
#include <QString>

#include <functional>
#include <optional>

namespace Fatek {

struct WatchItemSpec;

// What condition of an item raises an alarm (ISA-18.2 / IEC 62682 "alarm types").
enum class AlarmKind {
    HighHigh, // value >= limit
    High,     // value >= limit
    Low,      // value <= limit
    LowLow,   // value <= limit
    On,       // a bit is 1
    Off,      // a bit is 0
    Quality,  // the item is stale or in error (not read, refused by the PLC, link down)
};

// How urgently the operator must act; Critical first.
enum class AlarmPriority { Critical, High, Medium, Low };

// One alarm of one watch item, as the watch list file defines it. Limits are numbers in the
// item's format (ValueFormat::number: a float item's limit is a float, a signed item's may be
// negative). The raised condition must hold for onDelayMs, the cleared one for offDelayMs, both
// confirmed by a value read at least that long after the change; a limit alarm clears only when
// the value is past the limit by the deadband (high: value < limit - deadband). A quality alarm
// is raised when the item has been stale or in error for onDelayMs.
struct AlarmDefinition
{
    AlarmKind kind = AlarmKind::High;
    double limit = 0;
    double deadband = 0;
    int onDelayMs = 0;
    int offDelayMs = 0;
    AlarmPriority priority = AlarmPriority::Medium;
    QString message; // empty: the item's name or address and the kind ("R100 high")
    QString group;   // the plant area, for filtering
    // Out of service (ISA-18.2 "out of service"; disabled by design): never raised.
    bool enabled = true;

    bool operator==(const AlarmDefinition &) const = default;
};

namespace Alarms {

inline constexpr int MaxDelayMs = 24 * 3600 * 1000;

// File and MQTT names: "highHigh", "high", "low", "lowLow", "on", "off", "quality".
QString kindName(AlarmKind kind);
std::optional<AlarmKind> kindFromName(const QString &name);
QList<AlarmKind> allKinds();
// "critical", "high", "medium", "low".
QString priorityName(AlarmPriority priority);
std::optional<AlarmPriority> priorityFromName(const QString &name);
bool isLimitKind(AlarmKind kind);
bool isBitKind(AlarmKind kind);

// The alarm's id within its connection, stable across restarts and unique per item and kind:
// "1-R100-high" (station, address, kind). MQTT topics, the journal and the summary use it.
QString alarmId(const WatchItemSpec &item, AlarmKind kind);
// The text shown when the definition has none: "Tank level high" / "R100 high".
QString defaultMessage(const WatchItemSpec &item, AlarmKind kind);
QString messageOf(const WatchItemSpec &item, const AlarmDefinition &alarm);

// The alarms of one item, checked against it and each other: one alarm per kind; limit kinds on
// an item with a number (not bit, not ASCII), bit kinds on a 1-bit item; deadband and delays not
// negative, delays at most MaxDelayMs, no deadband on a bit or quality alarm; low-low <= low <
// high <= high-high where given. Errors start with "alarm N: " (N from 1).
Status validate(const WatchItemSpec &item);

// The item's "alarms" list of a watch list file: every key known (an unknown one is refused by
// name), each value of its type. `keyLine` gives the line of a key of alarm N (0 if unknown) so
// that the error names it.
Result<QList<AlarmDefinition>>
fromJson(const QJsonValue &value, const std::function<int(qsizetype, const QString &)> &keyLine);
QJsonValue toJson(const QList<AlarmDefinition> &alarms);

} // namespace Alarms

} // namespace Fatek
