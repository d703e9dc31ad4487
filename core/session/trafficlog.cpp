#include "trafficlog.h"

#include <QMutexLocker>

#include <algorithm>

namespace Fatek {

TrafficLog::TrafficLog(int capacity, QObject *parent)
    : QObject(parent)
    , m_capacity(std::max(1, capacity))
{}

int TrafficLog::capacity() const
{
    QMutexLocker locker(&m_mutex);
    return m_capacity;
}

void TrafficLog::setCapacity(int capacity)
{
    QMutexLocker locker(&m_mutex);
    m_capacity = std::max(1, capacity);
    while (m_entries.size() > static_cast<std::size_t>(m_capacity))
        m_entries.pop_front();
}

quint64 TrafficLog::append(TrafficEntry::Direction direction, const QByteArray &bytes,
                           const QString &summary, const QString &error)
{
    quint64 sequence = 0;
    {
        QMutexLocker locker(&m_mutex);
        sequence = ++m_lastSequence;
        m_entries.push_back(
            {sequence, QDateTime::currentDateTime(), direction, bytes, summary, error});
        while (m_entries.size() > static_cast<std::size_t>(m_capacity))
            m_entries.pop_front();
    }
    // Emitted outside the lock: a direct-connected slot may call entries().
    Q_EMIT entriesAdded(sequence);
    return sequence;
}

QList<TrafficEntry> TrafficLog::entries(quint64 after) const
{
    QMutexLocker locker(&m_mutex);
    QList<TrafficEntry> list;
    // Sequence numbers are consecutive, so the first wanted entry is found by arithmetic.
    if (m_entries.empty() || after >= m_lastSequence)
        return list;
    const quint64 first = m_entries.front().sequence;
    const std::size_t skip = after < first ? 0 : static_cast<std::size_t>(after - first + 1);
    list.reserve(static_cast<qsizetype>(m_entries.size() - skip));
    for (auto it = m_entries.begin() + static_cast<std::ptrdiff_t>(skip); it != m_entries.end();
         ++it)
        list.append(*it);
    return list;
}

int TrafficLog::size() const
{
    QMutexLocker locker(&m_mutex);
    return static_cast<int>(m_entries.size());
}

quint64 TrafficLog::lastSequence() const
{
    QMutexLocker locker(&m_mutex);
    return m_lastSequence;
}

void TrafficLog::clear()
{
    QMutexLocker locker(&m_mutex);
    m_entries.clear();
}

} // namespace Fatek
