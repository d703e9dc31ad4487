#include "statisticskeeper.h"

#include "sessionshared.h"

namespace Fatek {

StatisticsKeeper::StatisticsKeeper(std::shared_ptr<SessionShared> shared, QObject *parent)
    : QObject(parent)
    , m_shared(std::move(shared))
{
    m_timer.setInterval(250);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        publish();
        if (!m_dirty)
            return;
        m_dirty = false;
        Q_EMIT statisticsChanged(m_statistics);
    });
}

void StatisticsKeeper::startTimer()
{
    m_timer.start();
}

void StatisticsKeeper::count(quint8 station, const std::function<void(StationStatistics &)> &update)
{
    update(m_statistics.total);
    if (station != 0)
        update(m_statistics.stations[station]);
    changed();
}

void StatisticsKeeper::discardStale(quint64 staleBytes, quint64 partialBytes)
{
    m_statistics.bytesDiscarded += staleBytes + partialBytes;
    m_statistics.total.bytesIn += staleBytes;
}

void StatisticsKeeper::discardUnexpected(quint64 bytes)
{
    m_statistics.total.bytesIn += bytes;
    m_statistics.bytesDiscarded += bytes;
    changed();
}

void StatisticsKeeper::discardNoise(quint64 bytes)
{
    m_statistics.bytesDiscarded += bytes;
    changed();
}

void StatisticsKeeper::pollCycle(double ms)
{
    ++m_statistics.pollCycles;
    m_statistics.lastCycleMs = ms;
    changed();
}

void StatisticsKeeper::linkLost()
{
    ++m_statistics.linkLosses;
    changed();
}

void StatisticsKeeper::stationHealth(quint8 station, bool demoted, const QDateTime &nextTry)
{
    StationStatistics &stats = m_statistics.stations[station];
    stats.demoted = demoted;
    stats.nextTry = nextTry;
    if (demoted) {
        ++stats.demotions;
        ++m_statistics.total.demotions;
    }
    changed();
}

void StatisticsKeeper::reset()
{
    m_statistics = SessionStatistics();
    changed();
}

void StatisticsKeeper::changed()
{
    m_dirty = true;
    m_sharedStale = true;
}

void StatisticsKeeper::publish()
{
    // Copied for Session::statistics() once per finished request, not once per counter change;
    // the figures only, not the round-trip windows (docs/performance.md).
    if (!m_sharedStale)
        return;
    m_sharedStale = false;
    const std::lock_guard locker(m_shared->mutex);
    m_shared->statistics.assignFigures(m_statistics);
}

} // namespace Fatek
