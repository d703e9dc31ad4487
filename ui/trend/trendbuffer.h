#pragma once

#include "core/watch/watchlist.h"

#include <QList>
#include <QPointF>

#include <cstdint>
#include <optional>
#include <vector>

namespace Fatek {

// The number a trend plots for a raw watch value in the item's format: signed, unsigned, BCD,
// float and double as their value, hex and binary as signed, bits as 0/1 (ValueFormat::number,
// whatever the text format). Nothing for ASCII
// (text has no height) or a format that does not fit the item.
std::optional<double> trendValue(const WatchItemSpec &item, std::uint64_t raw);

// Samples of one trend item in a fixed-size ring (oldest dropped first), in time order. A gap
// sample marks "no fresh value from here on" (stale, error, paused): lines never bridge it.
class TrendBuffer
{
public:
    struct Sample
    {
        qint64 timeMs = 0; // ms since the epoch
        double value = 0;
        bool gap = false;
    };

    explicit TrendBuffer(qsizetype capacity = 100000);

    qsizetype capacity() const { return static_cast<qsizetype>(m_ring.size()); }
    qsizetype size() const { return m_size; }
    bool isEmpty() const { return m_size == 0; }
    const Sample &at(qsizetype i) const; // 0 = oldest
    const Sample &last() const { return at(m_size - 1); }

    // Samples must come in time order; an older one is dropped (clock steps back).
    void append(qint64 timeMs, double value);
    // Ends the current line (a no-op when the last sample is already a gap or there is none).
    void appendGap(qint64 timeMs);
    void clear();

    // Good samples (not gaps) in [fromMs, toMs].
    qsizetype countIn(qint64 fromMs, qint64 toMs) const;

    // The lines to draw for [fromMs, toMs]: one list of points per stretch without gaps
    // (x = ms since the epoch). With more than maxPoints samples in the range, each stretch is
    // cut into time buckets and every bucket keeps its first, minimum, maximum and last sample, so
    // peaks survive the decimation. The sample just outside each end is included so lines reach
    // the edges.
    QList<QList<QPointF>> segments(qint64 fromMs, qint64 toMs, qsizetype maxPoints = 2000) const;

private:
    std::vector<Sample> m_ring;
    qsizetype m_start = 0;
    qsizetype m_size = 0;
};

} // namespace Fatek
