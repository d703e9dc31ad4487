#pragma once

#include "historytypes.h"

#include <vector>

namespace Fatek {

// Turns the samples of one series (HistoryStore::samples: time order, the one before the range
// first) into what a trend draws of [fromMs, toMs) in `buckets` pixel columns: per column at most
// the first, minimum, maximum and last value, in time order, so peaks survive; with fewer samples
// than columns every sample is kept. A gap point ends the line where a sample has no value
// (stale, error, off) and where two samples are further apart than `maxSilenceMs` (nothing was
// recorded: the program was not running; the series' heartbeat tells how long a silence may be:
// History::maxSilenceMs). The sample before the range enters it at fromMs.
namespace HistoryReducer {

std::vector<HistoryPoint> reduce(const std::vector<HistorySample> &samples, qint64 fromMs,
                                 qint64 toMs, int buckets, qint64 maxSilenceMs);

} // namespace HistoryReducer

namespace History {
// The longest silence between two samples of a series with this heartbeat that still means
// "unchanged": twice the heartbeat plus 5 s of slack for a slow poll.
inline qint64 maxSilenceMs(int heartbeatS)
{
    return 2 * qint64(heartbeatS) * 1000 + 5000;
}
} // namespace History

} // namespace Fatek
