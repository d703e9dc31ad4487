#pragma once

#include <QDateTime>
#include <QList>
#include <QMap>
#include <QMetaType>

#include <cstdint>
#include <vector>

namespace Fatek {

// Counters of one station (or of the whole session). Every query attempt on the wire counts.
struct StationStatistics
{
    quint64 requests = 0;       // requests finished (each counted once, however many attempts)
    quint64 answers = 0;        // valid answer frames received (PLC errors included)
    quint64 timeouts = 0;       // attempts that got no complete answer in time
    quint64 checksumErrors = 0; // answer frames rejected for a bad LRC/CRC
    quint64 plcErrors = 0;      // answers carrying a non-zero PLC error code
    quint64 frameErrors = 0;    // answer frames rejected for broken framing or content
    quint64 retries = 0;        // attempts beyond the first
    // Requests in a row that got no answer at all (every attempt timed out); 0 again at the next
    // answer. Non-zero: the station is silent (wrong station number, PLC off, cable).
    quint64 unanswered = 0;
    // Polling of a silent station is demoted (issue 31): not polled until nextTry, then tried once.
    bool demoted = false;
    QDateTime nextTry; // UTC; valid while demoted
    quint64 demotions = 0;
    quint64 bytesOut = 0;
    quint64 bytesIn = 0;
    double rttLastMs = 0; // query written -> answer complete, last good answer
    double rttMeanMs = 0; // over every answer since the last reset
    double rttP50Ms = 0;  // over the last rttWindow answers
    double rttP99Ms = 0;

    static constexpr int rttWindow = 1024;

    // Adds a round-trip sample and updates last/mean/percentiles.
    void addRoundTrip(double ms);
    // Copies every public figure of `other`, not its window of samples (2 x 8 KB): for a
    // snapshot that is read, not counted into (SessionWorker publishes one per request).
    void assignFigures(const StationStatistics &other);

    bool operator==(const StationStatistics &other) const;

private:
    std::vector<double> m_window; // ring of the last rttWindow samples
    std::vector<double> m_sorted; // the same samples, sorted (percentiles without a sort)
    std::size_t m_next = 0;
    quint64 m_rttCount = 0;
};

// Totals of a session plus the same counters per station number.
struct SessionStatistics
{
    StationStatistics total;
    QMap<quint8, StationStatistics> stations;
    quint64 pollCycles = 0;     // poll cycles completed
    double lastCycleMs = 0;     // duration of the last poll cycle
    quint64 bytesDiscarded = 0; // stale or unexpected bytes thrown away (noise included)
    quint64 linkLosses = 0;     // times an open link failed (peer closed, cable pulled ...)

    // StationStatistics::assignFigures for the total and every station, in a station map of its
    // own: sharing `other`'s QMap would make `other`'s next count copy it whole, windows and all.
    void assignFigures(const SessionStatistics &other);
};

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::SessionStatistics)
