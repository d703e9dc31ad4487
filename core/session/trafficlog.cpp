#include "trafficlog.h"

#include "crossthreadcall.h"

#include <QMetaMethod>
#include <QThread>

#include <algorithm>

namespace Fatek {

TrafficLog::TrafficLog(int capacity, QObject *parent)
    : QObject(parent)
    , m_capacity(std::max(0, capacity))
{}

int TrafficLog::capacity() const
{
    const std::lock_guard locker(m_mutex);
    return m_capacity;
}

void TrafficLog::setCapacity(int capacity)
{
    const std::lock_guard locker(m_mutex);
    m_capacity = std::max(0, capacity);
    trimLocked();
}

void TrafficLog::growCapacity(int capacity)
{
    const std::lock_guard locker(m_mutex);
    m_capacity = std::max(m_capacity, capacity);
}

qint64 TrafficLog::byteBudget() const
{
    const std::lock_guard locker(m_mutex);
    return m_byteBudget;
}

void TrafficLog::setByteBudget(qint64 bytes)
{
    const std::lock_guard locker(m_mutex);
    m_byteBudget = std::max<qint64>(maxEntryBytes, bytes);
    trimLocked();
}

qint64 TrafficLog::bytesHeld() const
{
    const std::lock_guard locker(m_mutex);
    return m_bytesHeld;
}

void TrafficLog::trimLocked()
{
    while (!m_entries.empty()
           && (m_entries.size() > static_cast<std::size_t>(m_capacity)
               || m_bytesHeld > m_byteBudget)) {
        m_bytesHeld -= m_entries.front().bytes.size();
        m_entries.pop_front();
    }
}

quint64 TrafficLog::append(TrafficEntry::Direction direction, const QByteArray &bytes,
                           const Message &summary, const Message &error)
{
    quint64 sequence = 0;
    {
        const std::lock_guard locker(m_mutex);
        sequence = ++m_lastSequence;
        if (m_capacity == 0)
            return sequence; // off: nothing reads this log, nothing is kept or announced
        Message note = error;
        QByteArray kept = bytes;
        if (kept.size() > maxEntryBytes) {
            kept.truncate(maxEntryBytes);
            Message cut = msg<MsgId::LogBytesKept>(bytes.size(), maxEntryBytes);
            note = note.empty() ? std::move(cut) : msg<MsgId::Listed>(note, std::move(cut));
        }
        m_bytesHeld += kept.size();
        m_entries.push_back(
            {sequence, QDateTime::currentDateTimeUtc(), direction, kept, summary, note});
        trimLocked();
    }
    // Emitted outside the lock: a direct-connected slot may call entries().
    if (QThread::currentThread() == thread()) {
        Q_EMIT entriesAdded(sequence);
    } else if (isSignalConnected(QMetaMethod::fromSignal(&TrafficLog::entriesAdded))
               && !m_notifyPending.exchange(true)) {
        // Only for a listener (a console on screen): otherwise the post would wake the owner's
        // thread for nothing, about once per transaction. One that connects later reads the
        // entries already added (the entry is in before this check).
        // One notification in flight at most, however fast the worker appends.
        CrossThreadCall::post(this, [this] {
            m_notifyPending.store(false);
            Q_EMIT entriesAdded(lastSequence());
        });
    }
    return sequence;
}

bool TrafficLog::event(QEvent *event)
{
    return CrossThreadCall::deliver(this, event) || QObject::event(event);
}

QList<TrafficEntry> TrafficLog::entries(quint64 after) const
{
    const std::lock_guard locker(m_mutex);
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
    const std::lock_guard locker(m_mutex);
    return static_cast<int>(m_entries.size());
}

quint64 TrafficLog::lastSequence() const
{
    const std::lock_guard locker(m_mutex);
    return m_lastSequence;
}

void TrafficLog::clear()
{
    const std::lock_guard locker(m_mutex);
    m_entries.clear();
    m_bytesHeld = 0;
}

} // namespace Fatek
