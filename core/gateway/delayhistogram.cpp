#include "delayhistogram.h"

#include <algorithm>
#include <cmath>

namespace Fatek {

void DelayHistogram::add(std::int64_t ms)
{
    ms = std::max<std::int64_t>(ms, 0); // a clock step back reads as no delay
    ++m_buckets[static_cast<std::size_t>(std::min<std::int64_t>(ms, MaxMs))];
    ++m_count;
    m_max = std::max(m_max, ms);
}

void DelayHistogram::clear()
{
    m_buckets.fill(0);
    m_count = 0;
    m_max = 0;
}

std::int64_t DelayHistogram::percentile(double p) const
{
    if (m_count == 0)
        return 0;
    const auto rank = std::clamp<std::uint64_t>(
        static_cast<std::uint64_t>(std::ceil(p * static_cast<double>(m_count))), 1, m_count);
    std::uint64_t seen = 0;
    for (std::size_t ms = 0; ms < m_buckets.size(); ++ms) {
        seen += m_buckets[ms];
        if (seen >= rank)
            return ms == MaxMs ? m_max : static_cast<std::int64_t>(ms);
    }
    return m_max;
}

} // namespace Fatek
