#pragma once

#include "sessionstatistics.h"

#include <QObject>
#include <QTimer>

#include <functional>
#include <memory>

namespace Fatek {

struct SessionShared;

// The worker's counters: counted on the worker thread, copied to SessionShared for
// Session::statistics() and signalled at most 4 times a second, however busy the link.
class StatisticsKeeper : public QObject
{
    Q_OBJECT

public:
    StatisticsKeeper(std::shared_ptr<SessionShared> shared, QObject *parent);

    // On the worker thread (SessionWorker::startTimers()).
    void startTimer();
    // `update` on the session's total and, for a station other than 0, on that station.
    void count(quint8 station, const std::function<void(StationStatistics &)> &update);
    // Stale bytes (and a partial frame the deframers held) thrown away before an attempt.
    // Not marked as a change by itself: the attempt's own counts follow.
    void discardStale(quint64 staleBytes, quint64 partialBytes);
    // Bytes nobody asked for (a late answer, noise), received and thrown away.
    void discardUnexpected(quint64 bytes);
    // Noise the deframers skipped.
    void discardNoise(quint64 bytes);
    void pollCycle(double ms);
    // The line's round trip, p99 over the last answers (0 while none was measured).
    double roundTripP99Ms() const { return m_statistics.total.rttP99Ms; }
    void linkLost();
    void stationHealth(quint8 station, bool demoted, const QDateTime &nextTry);
    void reset();
    // Copies the figures to SessionShared if they changed since the last copy.
    void publish();

Q_SIGNALS:
    void statisticsChanged(const Fatek::SessionStatistics &statistics);

private:
    void changed();

    std::shared_ptr<SessionShared> m_shared;
    SessionStatistics m_statistics;
    bool m_dirty = false;       // statisticsChanged() due
    bool m_sharedStale = false; // SessionShared::statistics behind
    QTimer m_timer{this};
};

} // namespace Fatek
