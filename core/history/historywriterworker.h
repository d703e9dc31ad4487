#pragma once

#include "historystore.h"
#include "historytypes.h"

#include "core/protocol/message.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QSet>
#include <QTimer>

#include <any>
#include <deque>
#include <memory>

namespace Fatek {

class HistoryWriter;

// The part of HistoryWriter that lives on its thread: the store, the series' store ids and the
// samples not written yet. Only historywriter.cpp uses it; every call reaches it through a
// CrossThreadCall.
class HistoryWriterWorker : public QObject
{
public:
    HistoryWriterWorker(const QString &location, const HistoryRetention &retention,
                        HistoryWriter *writer);

    // The first open, and the clock of the batches (in this thread).
    void start();
    // A series of the writer's (new, or its label, format or heartbeat changed).
    void addSeries(qint64 handle, const HistorySeries &series);
    void record(std::vector<HistoryRecord> &records);
    // Writes what is pending now; false when it cannot (reported).
    bool write();
    void querySeries(quint64 ticket);
    void queryPoints(quint64 ticket, const QString &key, qint64 fromMs, qint64 toMs, int buckets);
    void querySamples(quint64 ticket, const QString &key, qint64 fromMs, qint64 toMs);
    // Answers `ticket` with nothing once what is pending is written (flush()).
    void flushed(quint64 ticket);
    // Writes what is pending and closes the store (the writer's destructor, before the thread
    // ends).
    void finish();

private:
    void tick();
    bool ensureOpen();
    bool resolveSeries();
    void retain();
    Result<HistorySeries> findSeries(const QString &key) const;
    ProtocolError unavailable() const;
    void fail(const Message &reason);
    void succeeded();
    void report(const Message &reason);
    void answer(quint64 ticket, std::any result);
    void publishPending();

    QString m_location;
    HistoryRetention m_retention;
    HistoryWriter *m_writer; // outlives this object: its destructor joins the thread
    std::unique_ptr<HistoryStore> m_store;
    QHash<qint64, HistorySeries> m_series; // handle -> series
    QHash<qint64, qint64> m_ids;           // handle -> the store's id
    QSet<qint64> m_unresolved;             // handles to ask the store about (new or changed)
    std::deque<HistoryRecord> m_pending;   // HistoryRecord::series is the handle
    QTimer *m_timer;
    QElapsedTimer m_sinceFailure;
    QElapsedTimer m_sinceRetention;
    bool m_failing = false;
    qint64 m_droppedWhileFailing = 0;
    Message m_lastReport;
    Message m_storeError; // why the store is not open
};

} // namespace Fatek
