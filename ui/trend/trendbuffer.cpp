#include "trendbuffer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace Fatek {

std::optional<double> trendValue(const WatchItemSpec &item, std::uint64_t raw)
{
    return ValueFormat::number(raw, ValueFormat::valueWidth(item.address, item.format), item.format,
                               item.swapWords);
}

TrendBuffer::TrendBuffer(qsizetype capacity)
    : m_ring(static_cast<std::size_t>(std::max<qsizetype>(capacity, 2)))
{}

const TrendBuffer::Sample &TrendBuffer::at(qsizetype i) const
{
    return m_ring[static_cast<std::size_t>((m_start + i) % capacity())];
}

void TrendBuffer::append(qint64 timeMs, double value)
{
    if (m_size > 0 && timeMs < last().timeMs)
        return;
    Sample s{timeMs, value, false};
    if (m_size < capacity()) {
        m_ring[static_cast<std::size_t>((m_start + m_size) % capacity())] = s;
        ++m_size;
    } else {
        m_ring[static_cast<std::size_t>(m_start)] = s;
        m_start = (m_start + 1) % capacity();
    }
}

void TrendBuffer::appendGap(qint64 timeMs)
{
    if (m_size == 0 || last().gap)
        return;
    append(std::max(timeMs, last().timeMs), 0);
    m_ring[static_cast<std::size_t>((m_start + m_size - 1) % capacity())].gap = true;
}

void TrendBuffer::clear()
{
    m_start = 0;
    m_size = 0;
}

qsizetype TrendBuffer::countIn(qint64 fromMs, qint64 toMs) const
{
    qsizetype n = 0;
    for (qsizetype i = 0; i < m_size; ++i) {
        const Sample &s = at(i);
        if (!s.gap && s.timeMs >= fromMs && s.timeMs <= toMs)
            ++n;
    }
    return n;
}

QList<QList<QPointF>> TrendBuffer::segments(qint64 fromMs, qint64 toMs, qsizetype maxPoints) const
{
    QList<QList<QPointF>> result;
    if (m_size == 0 || toMs < fromMs)
        return result;
    // First index with time >= fromMs (binary search over the ring), then one step back so the
    // line enters from the left edge.
    qsizetype lo = 0, hi = m_size;
    while (lo < hi) {
        const qsizetype mid = (lo + hi) / 2;
        if (at(mid).timeMs < fromMs)
            lo = mid + 1;
        else
            hi = mid;
    }
    qsizetype first = lo > 0 ? lo - 1 : 0;
    qsizetype end = lo;
    while (end < m_size && at(end).timeMs <= toMs)
        ++end;
    if (end < m_size)
        ++end; // one past the right edge
    const qsizetype count = end - first;
    const bool decimate = maxPoints > 0 && count > maxPoints;
    // Four points per bucket at most.
    const qint64 buckets = decimate ? std::max<qint64>(1, maxPoints / 4) : 0;
    const double bucketMs
        = decimate
              ? std::max(1.0, static_cast<double>(toMs - fromMs) / static_cast<double>(buckets))
              : 0;

    QList<QPointF> line;
    auto flushLine = [&] {
        if (!line.isEmpty())
            result.append(line);
        line.clear();
    };
    // Bucket state (decimation).
    qint64 bucket = -1;
    Sample bFirst, bMin, bMax, bLast;
    qsizetype bCount = 0;
    auto flushBucket = [&] {
        if (bCount == 0)
            return;
        Sample picks[4] = {bFirst, bMin, bMax, bLast};
        std::sort(std::begin(picks), std::end(picks),
                  [](const Sample &a, const Sample &b) { return a.timeMs < b.timeMs; });
        qint64 lastTime = -1;
        double lastValue = 0;
        for (const Sample &p : picks) {
            if (p.timeMs == lastTime && p.value == lastValue)
                continue;
            line.append(QPointF(static_cast<double>(p.timeMs), p.value));
            lastTime = p.timeMs;
            lastValue = p.value;
        }
        bCount = 0;
    };
    for (qsizetype i = first; i < end; ++i) {
        const Sample &s = at(i);
        if (s.gap) {
            flushBucket();
            flushLine();
            bucket = -1;
            continue;
        }
        if (!decimate) {
            line.append(QPointF(static_cast<double>(s.timeMs), s.value));
            continue;
        }
        const auto b
            = static_cast<qint64>(std::floor(static_cast<double>(s.timeMs - fromMs) / bucketMs));
        if (b != bucket) {
            flushBucket();
            bucket = b;
        }
        if (bCount == 0) {
            bFirst = bMin = bMax = s;
        } else {
            if (s.value < bMin.value)
                bMin = s;
            if (s.value > bMax.value)
                bMax = s;
        }
        bLast = s;
        ++bCount;
    }
    flushBucket();
    flushLine();
    return result;
}

} // namespace Fatek
