#pragma once

#include <array>
#include <cstdint>

namespace Fatek {

// Delays in whole milliseconds, counted in 1 ms buckets up to MaxMs (longer ones in the last
// bucket, their true maximum kept): constant memory and cost per sample however many items a link
// publishes between two statistics (a sorted window would cost a move per sample).
class DelayHistogram
{
public:
    static constexpr int MaxMs = 10000;

    void add(std::int64_t ms);
    void clear();
    std::uint64_t count() const { return m_count; }
    // Nearest-rank percentile (p in 0..1) in ms; 0 with no samples.
    std::int64_t percentile(double p) const;
    std::int64_t max() const { return m_max; }

private:
    std::array<std::uint32_t, MaxMs + 1> m_buckets{};
    std::uint64_t m_count = 0;
    std::int64_t m_max = 0;
};

} // namespace Fatek
