#pragma once

#include "core/qtbridge/qtmessage.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QMetaType>
#include <QObject>
#include <QString>

#include <atomic>
#include <deque>
#include <mutex>

namespace Fatek {

// One line of the traffic log.
struct TrafficEntry
{
    enum class Direction { Out, In, Event };

    quint64 sequence = 0; // increasing from 1, never reused (survives clear())
    QDateTime timestamp;  // UTC: cheap to take per frame on the worker; shown in local time
    Direction direction = Direction::Event;
    QByteArray bytes; // raw frame (empty for events such as a timeout)
    Message summary;  // decoded: "station 1, 46 read consecutive registers: 3 x R12"
    Message error;    // "no query pending", "No answer within 1000 ms."; empty when fine
};

// Every frame in and out of a session, bounded (oldest entries dropped). Written by the session's
// worker thread, read by any thread: all access is under a mutex. entriesAdded() is emitted in
// the log's own thread: at once for an append from that thread; appends from another thread are
// gathered into one signal per turn of the log thread's event loop.
class TrafficLog : public QObject
{
    Q_OBJECT

public:
    // A session keeps a short log until something shows it (the raw console), then the full one:
    // a studio whose console was never opened, or a program that only polls, needs no 10,000
    // frames per link (about 7 MB for a 200-item link).
    static constexpr int idleCapacity = 500;
    static constexpr int fullCapacity = 10000;

    explicit TrafficLog(int capacity = fullCapacity, QObject *parent = nullptr);

    int capacity() const;
    // Raises the capacity to at least `capacity` (never lowers it): a reader that starts showing
    // the log asks for the full one.
    void growCapacity(int capacity);
    // 0 turns the log off: entries are counted (sequence numbers) but not kept (a program that
    // never reads its session's traffic, such as the gateway, keeps no memory for it).
    void setCapacity(int capacity);
    // Besides the entry count, the frame bytes held are bounded too: a peer flooding the link
    // with large chunks cannot grow the log beyond this (oldest entries go first), and one entry
    // keeps at most maxEntryBytes of its bytes.
    static constexpr qsizetype maxEntryBytes = 4096;
    qint64 byteBudget() const;
    void setByteBudget(qint64 bytes);
    qint64 bytesHeld() const;

    // Returns the entry's sequence number.
    quint64 append(TrafficEntry::Direction direction, const QByteArray &bytes,
                   const Message &summary, const Message &error = {});

    // Entries with a sequence number above `after` still in the buffer (all with 0).
    QList<TrafficEntry> entries(quint64 after = 0) const;
    int size() const;
    quint64 lastSequence() const;
    void clear();

    // Runs the notifications posted from other threads (CrossThreadCall).
    bool event(QEvent *event) override;

Q_SIGNALS:
    // New entries up to `lastSequence`; fetch them with entries(previous).
    void entriesAdded(quint64 lastSequence);

private:
    mutable std::mutex m_mutex;
    std::deque<TrafficEntry> m_entries;
    void trimLocked();

    int m_capacity;
    qint64 m_byteBudget = 16 * 1024 * 1024;
    qint64 m_bytesHeld = 0;
    quint64 m_lastSequence = 0;
    std::atomic<bool> m_notifyPending{false};
};

} // namespace Fatek

Q_DECLARE_METATYPE(Fatek::TrafficEntry)
