#pragma once

#include "core/protocol/address.h"
#include "core/qtbridge/qtmessage.h"

#include <QDateTime>
#include <QMetaType>
#include <QString>

#include <cstdint>

namespace Fatek {

// One element to poll and how often.
struct WatchEntry
{
    std::uint64_t id = 0; // caller's handle, returned in WatchValue
    std::uint8_t station = 1;
    Address address;
    int intervalMs = 1000;
};

enum class ValueQuality {
    Good,  // read in this cycle
    Late,  // good when read, but no new value for twice the interval (the line is behind)
    Stale, // not read this cycle (timeout, link down): value is the last good one (0 if none)
    Error, // the PLC refuses this element (error A / 2) or it cannot be polled at all
};

struct WatchValue
{
    std::uint64_t itemId = 0;
    std::uint32_t value = 0; // raw: bit 0/1, 16-bit or 32-bit pattern
    QDateTime timestamp;     // when the answer came (for Stale: when it was last good)
    ValueQuality quality = ValueQuality::Error;
    Message error; // why not Good
};

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::WatchEntry)
Q_DECLARE_METATYPE(Fatek::WatchValue)
