#pragma once

#include <QString>

namespace Fatek {

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

} // namespace Fatek
