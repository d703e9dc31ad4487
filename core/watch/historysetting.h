#pragma once

#include "core/protocol/result.h"

#include <QJsonValue>
#include <QString>

#include <functional>
#include <optional>

namespace Fatek {

struct WatchItemSpec;

// How one watch item is recorded in the history (issue 51); an item without one is not
// recorded. In the watch list file: "history": {"deadband": 0.5, "heartbeatS": 600}, both keys
// optional ({} records every change with the default heartbeat).
struct HistorySetting
{
    // A change smaller than this (in the item's number, ValueFormat::number) from the last value
    // kept is not kept; 0: every change. Bits and ASCII items take no deadband.
    double deadband = 0;
    // A value is kept at least this often, changed or not, so that a flat line is known to be
    // flat (and a silence known to be a gap).
    int heartbeatS = 600;

    static constexpr int MinHeartbeatS = 1;
    static constexpr int MaxHeartbeatS = 24 * 3600;

    bool operator==(const HistorySetting &) const = default;
};

namespace HistorySettings {

// The item's setting checked against it: deadband finite and not negative, none on a bit or
// ASCII item (no number to measure it in), heartbeat from MinHeartbeatS to MaxHeartbeatS.
// Errors start with "history: ". Ok without a setting.
Status validate(const WatchItemSpec &item);

// The item's "history" object of a watch list file: every key known (an unknown one is refused
// by name), each value of its type. `keyLine` gives the line of a key (0 if unknown) so that the
// error names it. Nothing when the item has no "history".
Result<std::optional<HistorySetting>> fromJson(const QJsonValue &value,
                                               const std::function<int(const QString &)> &keyLine);
// Both keys, defaults too: the file shows what the item is recorded with.
QJsonValue toJson(const HistorySetting &setting);

} // namespace HistorySettings

} // namespace Fatek
