#include "historyreducer.h"

// One pass over the samples. A gap point's time is where the line ends: the value before it holds
// until then (a sample without a value: its time; a silence: the last sample's time plus the
// longest silence that still means "unchanged"). Per column the kept values form at most two runs,
// each reduced to its first, minimum, maximum and last: the one before the column's first gap and
// the one after it; a column that flaps between values and gaps keeps one gap and ends with
// another if it ends without a value (a pixel column cannot show more), so a column never yields
// more than ten points.

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace Fatek::HistoryReducer {

namespace {

struct Kept
{
    qint64 order = 0; // the sample's place: sorts and tells a point kept twice
    qint64 timeMs = 0;
    double value = 0;
};

class Reduction
{
public:
    Reduction(qint64 fromMs, qint64 toMs, int buckets, bool keepAll)
        : m_fromMs(fromMs)
        , m_spanMs(toMs - fromMs)
        , m_buckets(buckets)
        , m_keepAll(keepAll)
    {}

    void value(qint64 order, qint64 timeMs, double value)
    {
        enter(timeMs);
        m_inGap = false;
        m_trailingGap = false;
        const Kept kept{order, timeMs, value};
        if (m_keepAll) {
            m_points.push_back({timeMs, value, false});
            return;
        }
        if (!m_run) {
            m_run = Run{kept, kept, kept, kept};
            return;
        }
        if (value < m_run->min.value)
            m_run->min = kept;
        if (value > m_run->max.value)
            m_run->max = kept;
        m_run->last = kept;
    }

    void gap(qint64 timeMs)
    {
        if (m_inGap)
            return;
        enter(timeMs);
        m_inGap = true;
        if (!m_gapInBucket || m_keepAll) {
            flushRun();
            m_points.push_back({timeMs, 0, true});
            m_gapInBucket = true;
        } else {
            // A second gap in this column: said once, at the column's end, if no value follows.
            m_trailingGap = true;
            m_trailingGapMs = timeMs;
        }
    }

    std::vector<HistoryPoint> finish()
    {
        flushBucket();
        return std::move(m_points);
    }

private:
    struct Run
    {
        Kept first, min, max, last;
    };

    void enter(qint64 timeMs)
    {
        const qint64 bucket
            = std::clamp<qint64>((timeMs - m_fromMs) * m_buckets / m_spanMs, 0, m_buckets - 1);
        if (bucket == m_bucket)
            return;
        flushBucket();
        m_bucket = bucket;
    }

    void flushRun()
    {
        if (!m_run)
            return;
        std::array<Kept, 4> kept{m_run->first, m_run->min, m_run->max, m_run->last};
        std::sort(kept.begin(), kept.end(),
                  [](const Kept &a, const Kept &b) { return a.order < b.order; });
        for (std::size_t i = 0; i < kept.size(); ++i) {
            if (i == 0 || kept[i].order != kept[i - 1].order)
                m_points.push_back({kept[i].timeMs, kept[i].value, false});
        }
        m_run.reset();
    }

    void flushBucket()
    {
        flushRun();
        if (m_trailingGap)
            m_points.push_back({m_trailingGapMs, 0, true});
        m_trailingGap = false;
        m_gapInBucket = false;
    }

    const qint64 m_fromMs;
    const qint64 m_spanMs;
    const qint64 m_buckets;
    const bool m_keepAll;
    std::vector<HistoryPoint> m_points;
    std::optional<Run> m_run;
    qint64 m_bucket = -1;
    bool m_inGap = true; // no line yet
    bool m_gapInBucket = false;
    bool m_trailingGap = false;
    qint64 m_trailingGapMs = 0;
};

} // namespace

std::vector<HistoryPoint> reduce(const std::vector<HistorySample> &samples, qint64 fromMs,
                                 qint64 toMs, int buckets, qint64 maxSilenceMs)
{
    if (toMs <= fromMs || samples.empty())
        return {};
    buckets = std::max(buckets, 1);
    // The sample the line enters with: the last one before the range (normally the only one).
    const auto inRange
        = std::lower_bound(samples.begin(), samples.end(), fromMs,
                           [](const HistorySample &s, qint64 t) { return s.timeMs < t; });
    const auto end
        = std::lower_bound(inRange, samples.end(), toMs,
                           [](const HistorySample &s, qint64 t) { return s.timeMs < t; });
    const bool entering = inRange != samples.begin();
    const qint64 count = (end - inRange) + (entering ? 1 : 0);
    Reduction reduction(fromMs, toMs, buckets, count <= buckets);
    const bool silenceEnds = maxSilenceMs > 0;

    bool hasPrevious = false;
    bool previousHadValue = false;
    qint64 previousMs = 0;
    auto take = [&](qint64 order, const HistorySample &s, qint64 atMs) {
        // A silence ends the line where the last value stops being known.
        if (silenceEnds && hasPrevious && previousHadValue && s.timeMs - previousMs > maxSilenceMs)
            reduction.gap(std::max(previousMs + maxSilenceMs, fromMs));
        // A good sample without a number (an ASCII item) has nothing to draw either.
        const bool drawn = History::hasValue(s.quality) && !std::isnan(s.value);
        if (drawn)
            reduction.value(order, atMs, s.value);
        else
            reduction.gap(atMs);
        hasPrevious = true;
        previousHadValue = drawn;
        previousMs = s.timeMs;
    };
    if (entering) {
        const HistorySample &before = *(inRange - 1);
        // Too old to hold at fromMs: the range starts without a line (nothing to draw before).
        if (!silenceEnds || fromMs - before.timeMs <= maxSilenceMs)
            take(0, before, fromMs);
    }
    qint64 order = 1;
    for (auto it = inRange; it != end; ++it)
        take(order++, *it, it->timeMs);
    if (silenceEnds && hasPrevious && previousHadValue && previousMs + maxSilenceMs < toMs)
        reduction.gap(previousMs + maxSilenceMs);
    return reduction.finish();
}

} // namespace Fatek::HistoryReducer
