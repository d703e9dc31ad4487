#pragma once

#include "alarmtypes.h"

#include "core/protocol/message.h"
#include "core/protocol/result.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QThread>

#include <functional>

namespace Fatek {

class AlarmEngine;
class AlarmJournalWorker;

// The alarm journal of the studio and the gateway, on a thread of its own so that a slow disk
// never stalls the values or the UI: the AlarmJournal lives there and is touched there only; every
// hand-over is a queued call. Events are written in batches: at the next turn of the thread's
// event loop, and at most one transaction (one fsync) per 200 ms while they keep coming. A file
// that cannot be opened or written is reported (failed()) and the program keeps running: the
// batch is kept (up to 10,000 events, the oldest dropped beyond) and tried again every 5 s.
class AlarmJournalWriter : public QObject
{
    Q_OBJECT

public:
    using EventsCallback = std::function<void(const Result<QList<AlarmEvent>> &)>;

    // Opens (or creates) the file on the writer's thread at once; failed() says if it cannot.
    explicit AlarmJournalWriter(const QString &path, QObject *parent = nullptr);
    // Writes what is pending, closes the file and joins the thread.
    ~AlarmJournalWriter() override;

    QString path() const { return m_path; }

    // Holds the engine's evaluation (AlarmEngine::holdForRestore), loads the states the journal
    // kept for its connection and hands them to engine->restore() in the engine's thread (an
    // empty list when the file cannot be read: the alarms start from Normal), then records every
    // event of the engine. The engine lives in this object's thread; it may go away first.
    void attach(AlarmEngine *engine);

    // The events with fromMs <= time < toMs (of one connection, or all when empty), after what
    // is pending has been written. `callback` is called in `context`'s thread, unless `context`
    // is gone by then or this writer is destroyed first.
    void query(qint64 fromMs, qint64 toMs, const QString &connection, QObject *context,
               EventsCallback callback);

Q_SIGNALS:
    // The journal cannot be opened or written (said once per distinct reason).
    void failed(const Fatek::Message &reason);

private:
    friend class AlarmJournalWorker;

    // Called by the worker, through queued calls, in this object's thread.
    void statesLoaded(quint64 ticket, const Result<QList<AlarmRecord>> &records);
    void answered(quint64 ticket, const Result<QList<AlarmEvent>> &events);

    struct Query
    {
        QPointer<QObject> context;
        EventsCallback callback;
    };

    QString m_path;
    QThread m_thread;
    AlarmJournalWorker *m_worker = nullptr;
    quint64 m_nextTicket = 1;
    QHash<quint64, QPointer<AlarmEngine>> m_loading;
    QHash<quint64, Query> m_queries;
    QList<QMetaObject::Connection> m_connections;
};

} // namespace Fatek
