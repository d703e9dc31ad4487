#include "sessionstatistics.h"

#include <algorithm>
#include <cmath>

namespace Fatek {

void StationStatistics::addRoundTrip(double ms)
{
    rttLastMs = ms;
    ++m_rttCount;
    rttMeanMs += (ms - rttMeanMs) / static_cast<double>(m_rttCount);

    if (m_window.size() < static_cast<std::size_t>(rttWindow)) {
        m_window.push_back(ms);
    } else {
        m_window[m_next] = ms;
        m_next = (m_next + 1) % m_window.size();
    }
    // Nearest-rank percentiles over the window: at most 1024 samples, cheap enough per answer.
    std::vector<double> sorted = m_window;
    std::sort(sorted.begin(), sorted.end());
    const auto rank = [&sorted](double p) {
        const double n = static_cast<double>(sorted.size());
        auto index = static_cast<std::size_t>(std::ceil(p * n));
        index = std::clamp<std::size_t>(index, 1, sorted.size());
        return sorted[index - 1];
    };
    rttP50Ms = rank(0.50);
    rttP99Ms = rank(0.99);
}

bool StationStatistics::operator==(const StationStatistics &other) const
{
    return requests == other.requests && answers == other.answers && timeouts == other.timeouts
           && checksumErrors == other.checksumErrors && plcErrors == other.plcErrors
           && retries == other.retries && bytesOut == other.bytesOut && bytesIn == other.bytesIn
           && rttLastMs == other.rttLastMs && rttMeanMs == other.rttMeanMs;
}

} // namespace Fatek
