#include "alarmjournalwriter.h"

#include "alarmengine.h"
#include "alarmjournalworker.h"

#include "core/qtbridge/qtmessage.h"
#include "core/session/crossthreadcall.h"

namespace Fatek {

namespace {

// One transaction (one fsync with synchronous=FULL) per this much while events keep coming: an
// alarm flood costs a few commits a second, a lone event is written at once.
constexpr int BatchMs = 200;
// While the file cannot be written, the batch is tried again this often.
constexpr int RetryMs = 5000;
// The batch kept while the file cannot be written (the oldest dropped beyond).
constexpr qsizetype MaxPending = 10000;

} // namespace

AlarmJournalWorker::AlarmJournalWorker(const QString &path, AlarmJournalWriter *writer)
    : m_path(path)
    , m_writer(writer)
    , m_timer(new QTimer(this))
{
    m_timer->setSingleShot(true);
    connect(m_timer, &QTimer::timeout, this, &AlarmJournalWorker::flush);
}

bool AlarmJournalWorker::ensureOpen()
{
    if (m_journal)
        return true;
    Result<std::unique_ptr<AlarmJournal>> opened = AlarmJournal::open(m_path);
    if (!opened) {
        report(opened.error().message);
        return false;
    }
    m_journal = std::move(opened).value();
    m_lastReport = {};
    return true;
}

void AlarmJournalWorker::report(const Message &reason)
{
    if (reason == m_lastReport)
        return;
    m_lastReport = reason;
    AlarmJournalWriter *writer = m_writer;
    CrossThreadCall::invoke(writer, [writer, reason] { Q_EMIT writer->failed(reason); });
}

void AlarmJournalWorker::record(const AlarmEvent &event, const AlarmRecord &record)
{
    m_events.append(event);
    if (m_events.size() > MaxPending)
        m_events.remove(0, m_events.size() - MaxPending);
    const QString key = record.connection + QLatin1Char('\n') + record.alarmId;
    if (const auto it = m_recordIndex.constFind(key); it != m_recordIndex.constEnd()) {
        m_records[*it] = record;
    } else {
        m_recordIndex.insert(key, m_records.size());
        m_records.append(record);
    }
    schedule();
}

void AlarmJournalWorker::schedule()
{
    if (m_timer->isActive())
        return;
    const qint64 since = m_sinceWrite.isValid() ? m_sinceWrite.elapsed() : BatchMs;
    m_timer->start(static_cast<int>(qMax<qint64>(0, BatchMs - since)));
}

void AlarmJournalWorker::flush()
{
    if (m_events.isEmpty() && m_records.isEmpty())
        return;
    m_timer->stop();
    Status written = ensureOpen() ? m_journal->append(m_events, m_records) : Status(Ok{});
    if (!m_journal || !written) {
        if (!written)
            report(written.error().message);
        m_timer->start(RetryMs);
        return;
    }
    m_lastReport = {};
    m_events.clear();
    m_records.clear();
    m_recordIndex.clear();
    m_sinceWrite.start();
}

void AlarmJournalWorker::load(quint64 ticket, const QString &connection)
{
    Result<QList<AlarmRecord>> records = ensureOpen()
                                             ? m_journal->states(connection)
                                             : Result<QList<AlarmRecord>>(QList<AlarmRecord>{});
    if (!records)
        report(records.error().message);
    AlarmJournalWriter *writer = m_writer;
    CrossThreadCall::invoke(writer,
                            [writer, ticket, records] { writer->statesLoaded(ticket, records); });
}

void AlarmJournalWorker::query(quint64 ticket, qint64 fromMs, qint64 toMs,
                               const QString &connection)
{
    flush();
    Result<QList<AlarmEvent>> events
        = ensureOpen()
              ? m_journal->events(fromMs, toMs, connection)
              : Result<QList<AlarmEvent>>(makeError(ErrorKind::InvalidRequest, m_lastReport));
    AlarmJournalWriter *writer = m_writer;
    CrossThreadCall::invoke(writer, [writer, ticket, events] { writer->answered(ticket, events); });
}

void AlarmJournalWorker::finish()
{
    flush();
    m_timer->stop();
    m_journal.reset();
}

AlarmJournalWriter::AlarmJournalWriter(const QString &path, QObject *parent)
    : QObject(parent)
    , m_path(path)
    , m_worker(new AlarmJournalWorker(path, this))
{
    qRegisterMetaType<Fatek::Message>();
    qRegisterMetaType<Fatek::AlarmEvent>();
    qRegisterMetaType<Fatek::AlarmRecord>();
    m_thread.setObjectName(QStringLiteral("alarm journal"));
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    m_thread.start();
    AlarmJournalWorker *worker = m_worker;
    CrossThreadCall::invoke(worker, [worker] { worker->ensureOpen(); });
}

AlarmJournalWriter::~AlarmJournalWriter()
{
    for (const QMetaObject::Connection &c : std::as_const(m_connections))
        disconnect(c);
    // Queued calls run in order: every event posted before this one is written by finish().
    // Every call posted before this one runs first: finish() writes every event recorded.
    AlarmJournalWorker *worker = m_worker;
    QThread *thread = &m_thread;
    const void *channel = this;
    CrossThreadCall::invoke(worker, [worker, thread, channel] {
        worker->finish();
        CrossThreadCall::threadEnds(channel);
        thread->quit();
    });
    m_thread.wait();
    CrossThreadCall::threadEnded(channel);
}

void AlarmJournalWriter::attach(AlarmEngine *engine)
{
    engine->holdForRestore();
    const quint64 ticket = m_nextTicket++;
    m_loading.insert(ticket, engine);
    AlarmJournalWorker *worker = m_worker;
    const QString connection = engine->connection();
    CrossThreadCall::invoke(worker,
                            [worker, ticket, connection] { worker->load(ticket, connection); });
    // Each event is copied into a call to the worker's thread (marked for ThreadSanitizer: a
    // queued signal's copy is ordered by Qt's own mutex, which it cannot see).
    m_connections.append(connect(engine, &AlarmEngine::alarmEvent, this,
                                 [worker](const AlarmEvent &event, const AlarmRecord &record) {
                                     CrossThreadCall::invoke(worker, [worker, event, record] {
                                         worker->record(event, record);
                                     });
                                 }));
}

void AlarmJournalWriter::statesLoaded(quint64 ticket, const Result<QList<AlarmRecord>> &records)
{
    const QPointer<AlarmEngine> engine = m_loading.take(ticket);
    if (!engine)
        return;
    // Even without the journal's states the hold must end, or the alarms would never be raised.
    engine->restore(records ? *records : QList<AlarmRecord>{});
}

void AlarmJournalWriter::query(qint64 fromMs, qint64 toMs, const QString &connection,
                               QObject *context, EventsCallback callback)
{
    const quint64 ticket = m_nextTicket++;
    m_queries.insert(ticket, Query{context, std::move(callback)});
    AlarmJournalWorker *worker = m_worker;
    CrossThreadCall::invoke(worker, [worker, ticket, fromMs, toMs, connection] {
        worker->query(ticket, fromMs, toMs, connection);
    });
}

void AlarmJournalWriter::answered(quint64 ticket, const Result<QList<AlarmEvent>> &events)
{
    Query query = m_queries.take(ticket);
    if (!query.context || !query.callback)
        return;
    QMetaObject::invokeMethod(
        query.context.data(), [callback = std::move(query.callback), events] { callback(events); },
        Qt::AutoConnection);
}

} // namespace Fatek
