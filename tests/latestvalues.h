#pragma once

#include "core/watch/itemassembler.h"

#include <QHash>
#include <QList>

namespace TestUtil {

// The latest value of every item, as a table keeps them (tests of links and of the plant).
struct LatestValues
{
    QHash<std::uint64_t, Fatek::WatchItemValue> values;
    int batches = 0;

    void take(const QList<Fatek::WatchItemValue> &batch)
    {
        ++batches;
        for (const Fatek::WatchItemValue &v : batch)
            values.insert(v.key, v);
    }
    // Read in the last report that had it, with this raw value.
    bool good(std::uint64_t key, std::uint64_t raw) const
    {
        const Fatek::WatchItemValue v = values.value(key);
        return v.quality == Fatek::ValueQuality::Good && v.hasValue && v.raw == raw;
    }
};

} // namespace TestUtil
