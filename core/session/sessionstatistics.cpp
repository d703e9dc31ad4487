#include "sessionstatistics.h"

#include <algorithm>
#include <cmath>

namespace Fatek {

void StationStatistics::addRoundTrip(double ms)
{
    rttLastMs = ms;
    ++m_rttCount;
    rttMeanMs += (ms - rttMeanMs) / static_cast<double>(m_rttCount);

    // The sorted copy follows the ring: one sample out, one in (a binary search and a short
    // move each), so the percentiles cost no sort per answer (docs/performance.md).
    if (m_window.size() < static_cast<std::size_t>(rttWindow)) {
        m_window.push_back(ms);
    } else {
        const double old = m_window[m_next];
        m_sorted.erase(std::lower_bound(m_sorted.begin(), m_sorted.end(), old));
        m_window[m_next] = ms;
        m_next = (m_next + 1) % m_window.size();
    }
    m_sorted.insert(std::upper_bound(m_sorted.begin(), m_sorted.end(), ms), ms);
    // Nearest-rank percentiles over the window.
    const auto rank = [this](double p) {
        const double n = static_cast<double>(m_sorted.size());
        auto index = static_cast<std::size_t>(std::ceil(p * n));
        index = std::clamp<std::size_t>(index, 1, m_sorted.size());
        return m_sorted[index - 1];
    };
    rttP50Ms = rank(0.50);
    rttP99Ms = rank(0.99);
}

void StationStatistics::assignFigures(const StationStatistics &other)
{
    // Every public field (as operator== lists them, plus the percentiles).
    requests = other.requests;
    answers = other.answers;
    timeouts = other.timeouts;
    checksumErrors = other.checksumErrors;
    plcErrors = other.plcErrors;
    frameErrors = other.frameErrors;
    retries = other.retries;
    unanswered = other.unanswered;
    demoted = other.demoted;
    nextTry = other.nextTry;
    demotions = other.demotions;
    bytesOut = other.bytesOut;
    bytesIn = other.bytesIn;
    rttLastMs = other.rttLastMs;
    rttMeanMs = other.rttMeanMs;
    rttP50Ms = other.rttP50Ms;
    rttP99Ms = other.rttP99Ms;
}

bool StationStatistics::operator==(const StationStatistics &other) const
{
    return requests == other.requests && answers == other.answers && timeouts == other.timeouts
           && checksumErrors == other.checksumErrors && plcErrors == other.plcErrors
           && frameErrors == other.frameErrors && retries == other.retries
           && unanswered == other.unanswered && demoted == other.demoted && nextTry == other.nextTry
           && demotions == other.demotions && bytesOut == other.bytesOut && bytesIn == other.bytesIn
           && rttLastMs == other.rttLastMs && rttMeanMs == other.rttMeanMs;
}

void SessionStatistics::assignFigures(const SessionStatistics &other)
{
    total.assignFigures(other.total);
    // A new map, not `stations` changed in place: a copy handed out by Session::statistics()
    // may still share it (Qt's implicit sharing), on another thread.
    QMap<quint8, StationStatistics> figures;
    for (auto it = other.stations.cbegin(); it != other.stations.cend(); ++it)
        figures[it.key()].assignFigures(it.value());
    stations = std::move(figures);
    pollCycles = other.pollCycles;
    lastCycleMs = other.lastCycleMs;
    bytesDiscarded = other.bytesDiscarded;
    linkLosses = other.linkLosses;
}

} // namespace Fatek
