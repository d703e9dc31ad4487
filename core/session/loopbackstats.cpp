#include "loopbackstats.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace Fatek {

void LoopbackStats::add(Outcome outcome, double rttMs)
{
    switch (outcome) {
    case Outcome::Success: ++m_successes; break;
    case Outcome::Mismatch: ++m_mismatches; break;
    case Outcome::Timeout: ++m_timeouts; return;
    case Outcome::Error: ++m_errors; return;
    }
    m_rtts.push_back(rttMs);
    m_sum += rttMs;
}

void LoopbackStats::reset()
{
    *this = LoopbackStats();
}

double LoopbackStats::minMs() const
{
    return m_rtts.empty() ? 0 : *std::min_element(m_rtts.begin(), m_rtts.end());
}

double LoopbackStats::maxMs() const
{
    return m_rtts.empty() ? 0 : *std::max_element(m_rtts.begin(), m_rtts.end());
}

double LoopbackStats::meanMs() const
{
    return m_rtts.empty() ? 0 : m_sum / static_cast<double>(m_rtts.size());
}

double LoopbackStats::p99Ms() const
{
    if (m_rtts.empty())
        return 0;
    std::vector<double> sorted = m_rtts;
    std::sort(sorted.begin(), sorted.end());
    const auto rank
        = static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(sorted.size())));
    return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

QString LoopbackStats::summary() const
{
    QString text
        = QCoreApplication::translate("Fatek::LoopbackStats",
                                      "%1 runs: %2 OK, %3 mismatch, %4 timeout, %5 other errors")
              .arg(runs())
              .arg(m_successes)
              .arg(m_mismatches)
              .arg(m_timeouts)
              .arg(m_errors);
    if (hasRoundTrips()) {
        text += QCoreApplication::translate(
                    "Fatek::LoopbackStats",
                    " \u2014 round trip min %1 / mean %2 / max %3 / p99 %4 ms")
                    .arg(minMs(), 0, 'f', 1)
                    .arg(meanMs(), 0, 'f', 1)
                    .arg(maxMs(), 0, 'f', 1)
                    .arg(p99Ms(), 0, 'f', 1);
    }
    return text;
}

} // namespace Fatek
