#pragma once

#include <QString>

#include <vector>

namespace Fatek {

// Tally of a loopback test: outcomes and round-trip times (min / mean / max / p99). One tally for
// the GUI's loopback dialog and `fatek-cli loopback`, so both count a series the same way.
class LoopbackStats
{
public:
    enum class Outcome { Success, Mismatch, Timeout, Error };

    // rttMs is only used for answers (success and mismatch).
    void add(Outcome outcome, double rttMs = 0);
    void reset();

    int runs() const { return m_successes + m_mismatches + m_timeouts + m_errors; }
    int successes() const { return m_successes; }
    int mismatches() const { return m_mismatches; }
    int timeouts() const { return m_timeouts; }
    int errors() const { return m_errors; }

    bool hasRoundTrips() const { return !m_rtts.empty(); }
    double minMs() const;
    double maxMs() const;
    double meanMs() const;
    // Nearest-rank 99th percentile.
    double p99Ms() const;

    // "100 runs: 98 OK, 1 mismatch, 1 timeout, 0 other errors — RTT min 1.2 / mean 2.0 / max 9.1 /
    // p99 8.7 ms"
    QString summary() const;

private:
    int m_successes = 0;
    int m_mismatches = 0;
    int m_timeouts = 0;
    int m_errors = 0;
    std::vector<double> m_rtts;
    double m_sum = 0;
};

} // namespace Fatek
