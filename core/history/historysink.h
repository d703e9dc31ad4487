#pragma once

#include "historytypes.h"

#include <vector>

namespace Fatek {

// Where a HistoryRecorder hands what it decided to keep: HistoryWriter (a store on its own
// thread). Called in the recorder's thread only.
class HistorySink
{
public:
    HistorySink() = default;
    HistorySink(const HistorySink &) = delete;
    HistorySink &operator=(const HistorySink &) = delete;
    virtual ~HistorySink() = default;

    // A handle for the series (series.id is ignored), the same for the same key every time;
    // a changed label, format or heartbeat is passed on to the store.
    virtual qint64 addSeries(const HistorySeries &series) = 0;
    // Samples of series added here (HistoryRecord::series is addSeries' handle), in time order
    // per series.
    virtual void record(std::vector<HistoryRecord> records) = 0;
};

} // namespace Fatek
