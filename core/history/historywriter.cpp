#include "historywriter.h"

#include "historymessages.h"
#include "historyreducer.h"
#include "historywriterworker.h"

#include "core/qtbridge/qtmessage.h"
#include "core/session/crossthreadcall.h"

#include <QDateTime>

#include <algorithm>

namespace Fatek {

namespace {

// One transaction a second: a kill -9 loses at most the last second, and a value costs a bound
// parameter set, not a commit.
constexpr int BatchMs = 1000;
// While the store cannot be opened or written, it is tried again this often.
constexpr qint64 RetryMs = 5000;
// Retention while running (and once at open).
constexpr qint64 RetentionMs = 60'000;

} // namespace

HistoryWriterWorker::HistoryWriterWorker(const QString &location, const HistoryRetention &retention,
                                         HistoryWriter *writer)
    : m_location(location)
    , m_retention(retention)
    , m_writer(writer)
    , m_timer(new QTimer(this))
{
    m_timer->setInterval(BatchMs);
    connect(m_timer, &QTimer::timeout, this, &HistoryWriterWorker::tick);
}

void HistoryWriterWorker::start()
{
    m_timer->start();
    ensureOpen();
}

void HistoryWriterWorker::tick()
{
    if (m_failing && m_sinceFailure.elapsed() < RetryMs)
        return;
    // A store that failed is opened again at the retry even with nothing to write, so that
    // recovered() comes when it is back.
    if (!ensureOpen())
        return;
    if (write() && m_sinceRetention.hasExpired(RetentionMs))
        retain();
}

bool HistoryWriterWorker::ensureOpen()
{
    if (m_store)
        return true;
    Result<std::unique_ptr<HistoryStore>> opened
        = HistoryStore::open(m_location, HistoryStore::Mode::ReadWrite);
    if (!opened) {
        m_storeError = opened.error().message;
        fail(m_storeError);
        return false;
    }
    m_store = std::move(opened).value();
    m_storeError = {};
    // Every series again: ids are the store's, and this may be another store than before.
    m_ids.clear();
    for (auto it = m_series.cbegin(); it != m_series.cend(); ++it)
        m_unresolved.insert(it.key());
    retain();
    return true;
}

// The store's id of every series added or changed since (a change updates its label, format or
// heartbeat there).
bool HistoryWriterWorker::resolveSeries()
{
    for (auto it = m_unresolved.begin(); it != m_unresolved.end();) {
        const Result<qint64> id = m_store->seriesId(m_series.value(*it));
        if (!id) {
            fail(id.error().message);
            return false;
        }
        m_ids.insert(*it, *id);
        it = m_unresolved.erase(it);
    }
    return true;
}

void HistoryWriterWorker::retain()
{
    m_sinceRetention.start();
    if (m_retention.maxAgeS <= 0 && m_retention.maxBytes <= 0)
        return;
    const Result<HistoryRetentionOutcome> outcome
        = m_store->applyRetention(m_retention, QDateTime::currentMSecsSinceEpoch());
    if (!outcome) {
        // Not a failure of the values: they are written; retention is tried at the next minute.
        report(outcome.error().message);
        return;
    }
    m_writer->m_retained.fetch_add(outcome->samplesRemoved, std::memory_order_relaxed);
}

void HistoryWriterWorker::addSeries(qint64 handle, const HistorySeries &series)
{
    m_series.insert(handle, series);
    m_unresolved.insert(handle);
    if (m_store && !m_failing)
        resolveSeries();
}

void HistoryWriterWorker::record(std::vector<HistoryRecord> &records)
{
    m_pending.insert(m_pending.end(), std::make_move_iterator(records.begin()),
                     std::make_move_iterator(records.end()));
    if (const qsizetype excess = qsizetype(m_pending.size()) - HistoryWriter::MaxPending;
        excess > 0) {
        m_pending.erase(m_pending.begin(), m_pending.begin() + excess);
        m_droppedWhileFailing += excess;
        m_writer->m_dropped.fetch_add(excess, std::memory_order_relaxed);
    }
    publishPending();
}

void HistoryWriterWorker::publishPending()
{
    m_writer->m_pending.store(qint64(m_pending.size()), std::memory_order_relaxed);
}

bool HistoryWriterWorker::write()
{
    if (!ensureOpen() || !resolveSeries())
        return false;
    if (m_pending.empty()) {
        succeeded();
        return true;
    }
    // Samples of a series whose id the store has not given yet wait for the next batch.
    std::vector<HistoryRecord> batch;
    batch.reserve(m_pending.size());
    std::deque<HistoryRecord> waiting;
    for (const HistoryRecord &r : m_pending) {
        if (const auto id = m_ids.constFind(r.series); id != m_ids.constEnd())
            batch.push_back({*id, r.sample});
        else
            waiting.push_back(r);
    }
    if (!batch.empty()) {
        if (Status written = m_store->append(batch); !written) {
            fail(written.error().message);
            return false;
        }
        m_writer->m_written.fetch_add(qint64(batch.size()), std::memory_order_relaxed);
        m_writer->m_transactions.fetch_add(1, std::memory_order_relaxed);
    }
    m_pending = std::move(waiting);
    publishPending();
    succeeded();
    return true;
}

void HistoryWriterWorker::fail(const Message &reason)
{
    if (!m_failing)
        m_droppedWhileFailing = 0;
    m_failing = true;
    m_sinceFailure.start();
    report(reason);
}

void HistoryWriterWorker::succeeded()
{
    // A reason said while the values were written (retention) stays said until a failure ends.
    if (!m_failing)
        return;
    m_failing = false;
    m_lastReport = {};
    HistoryWriter *writer = m_writer;
    if (m_droppedWhileFailing > 0) {
        report(msg<MsgId::HistorySamplesDropped>(m_store->location().toStdString(),
                                                 m_droppedWhileFailing));
        m_lastReport = {};
        m_droppedWhileFailing = 0;
    }
    CrossThreadCall::invoke(writer, [writer] { Q_EMIT writer->recovered(); });
}

void HistoryWriterWorker::report(const Message &reason)
{
    if (reason == m_lastReport)
        return;
    m_lastReport = reason;
    HistoryWriter *writer = m_writer;
    CrossThreadCall::invoke(writer, [writer, reason] { Q_EMIT writer->failed(reason); });
}

ProtocolError HistoryWriterWorker::unavailable() const
{
    return makeError(ErrorKind::InvalidRequest, m_storeError);
}

Result<HistorySeries> HistoryWriterWorker::findSeries(const QString &key) const
{
    const Result<QList<HistorySeries>> all = m_store->series();
    if (!all)
        return all.error();
    const auto found = std::find_if(all->cbegin(), all->cend(),
                                    [&key](const HistorySeries &s) { return s.key() == key; });
    if (found == all->cend())
        return makeError(
            ErrorKind::InvalidRequest,
            msg<MsgId::HistoryUnknownSeries>(m_store->location().toStdString(), key.toStdString()));
    return *found;
}

void HistoryWriterWorker::answer(quint64 ticket, std::any result)
{
    HistoryWriter *writer = m_writer;
    CrossThreadCall::invoke(
        writer, [writer, ticket, result = std::move(result)] { writer->answered(ticket, result); });
}

// A query reads what was recorded until it was asked: what is pending is written first (a store
// that fails is read all the same, without it).
void HistoryWriterWorker::querySeries(quint64 ticket)
{
    write();
    answer(ticket, m_store ? m_store->series() : Result<QList<HistorySeries>>(unavailable()));
}

void HistoryWriterWorker::queryPoints(quint64 ticket, const QString &key, qint64 fromMs,
                                      qint64 toMs, int buckets)
{
    write();
    auto points = [&]() -> Result<std::vector<HistoryPoint>> {
        if (!m_store)
            return unavailable();
        const Result<HistorySeries> series = findSeries(key);
        if (!series)
            return series.error();
        const Result<std::vector<HistorySample>> samples
            = m_store->samples(series->id, fromMs, toMs);
        if (!samples)
            return samples.error();
        return HistoryReducer::reduce(*samples, fromMs, toMs, buckets,
                                      History::maxSilenceMs(series->heartbeatS));
    };
    answer(ticket, points());
}

void HistoryWriterWorker::querySamples(quint64 ticket, const QString &key, qint64 fromMs,
                                       qint64 toMs)
{
    write();
    auto samples = [&]() -> Result<std::vector<HistorySample>> {
        if (!m_store)
            return unavailable();
        const Result<HistorySeries> series = findSeries(key);
        if (!series)
            return series.error();
        return m_store->samples(series->id, fromMs, toMs);
    };
    answer(ticket, samples());
}

void HistoryWriterWorker::flushed(quint64 ticket)
{
    write();
    answer(ticket, {});
}

void HistoryWriterWorker::finish()
{
    write();
    m_timer->stop();
    m_store.reset();
}

HistoryWriter::HistoryWriter(const QString &location, const HistoryRetention &retention,
                             QObject *parent)
    : QObject(parent)
    , m_location(location)
    , m_worker(new HistoryWriterWorker(location, retention, this))
{
    qRegisterMetaType<Fatek::Message>();
    m_thread.setObjectName(QStringLiteral("history"));
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    m_thread.start();
    HistoryWriterWorker *worker = m_worker;
    CrossThreadCall::invoke(worker, [worker] { worker->start(); });
}

HistoryWriter::~HistoryWriter()
{
    // Every call posted before this one runs first: finish() writes every sample recorded.
    HistoryWriterWorker *worker = m_worker;
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

HistoryWriter::Statistics HistoryWriter::statistics() const
{
    Statistics s;
    s.written = m_written.load(std::memory_order_relaxed);
    s.pending = m_pending.load(std::memory_order_relaxed);
    s.dropped = m_dropped.load(std::memory_order_relaxed);
    s.transactions = m_transactions.load(std::memory_order_relaxed);
    s.retained = m_retained.load(std::memory_order_relaxed);
    return s;
}

qint64 HistoryWriter::addSeries(const HistorySeries &series)
{
    const QString key = series.key();
    qint64 handle = m_handles.value(key);
    if (handle > 0) {
        const HistorySeries &known = m_series.at(handle - 1);
        if (known.label == series.label && known.format == series.format
            && known.heartbeatS == series.heartbeatS)
            return handle;
        m_series[handle - 1] = series;
    } else {
        m_series.append(series);
        handle = m_series.size();
        m_handles.insert(key, handle);
    }
    HistorySeries copy = series;
    copy.id = 0;
    HistoryWriterWorker *worker = m_worker;
    CrossThreadCall::invoke(worker, [worker, handle, copy] { worker->addSeries(handle, copy); });
    return handle;
}

void HistoryWriter::record(std::vector<HistoryRecord> records)
{
    if (records.empty())
        return;
    HistoryWriterWorker *worker = m_worker;
    CrossThreadCall::invoke(
        worker, [worker, records = std::move(records)]() mutable { worker->record(records); });
}

quint64 HistoryWriter::ask(QObject *context, std::function<void(const std::any &)> deliver)
{
    const quint64 ticket = m_nextTicket++;
    m_queries.insert(ticket, Query{context, std::move(deliver)});
    return ticket;
}

void HistoryWriter::answered(quint64 ticket, const std::any &result)
{
    Query query = m_queries.take(ticket);
    if (!query.context || !query.deliver)
        return;
    CrossThreadCall::invoke(query.context.data(),
                            [deliver = std::move(query.deliver), result] { deliver(result); });
}

void HistoryWriter::flush(std::function<void()> done)
{
    const quint64 ticket = ask(this, [done = std::move(done)](const std::any &) {
        if (done)
            done();
    });
    HistoryWriterWorker *worker = m_worker;
    CrossThreadCall::invoke(worker, [worker, ticket] { worker->flushed(ticket); });
}

void HistoryWriter::querySeries(QObject *context, SeriesCallback callback)
{
    const quint64 ticket = ask(context, [callback = std::move(callback)](const std::any &result) {
        callback(std::any_cast<const Result<QList<HistorySeries>> &>(result));
    });
    HistoryWriterWorker *worker = m_worker;
    CrossThreadCall::invoke(worker, [worker, ticket] { worker->querySeries(ticket); });
}

void HistoryWriter::queryPoints(const QString &seriesKey, qint64 fromMs, qint64 toMs, int buckets,
                                QObject *context, PointsCallback callback)
{
    const quint64 ticket = ask(context, [callback = std::move(callback)](const std::any &result) {
        callback(std::any_cast<const Result<std::vector<HistoryPoint>> &>(result));
    });
    HistoryWriterWorker *worker = m_worker;
    CrossThreadCall::invoke(worker, [worker, ticket, seriesKey, fromMs, toMs, buckets] {
        worker->queryPoints(ticket, seriesKey, fromMs, toMs, buckets);
    });
}

void HistoryWriter::querySamples(const QString &seriesKey, qint64 fromMs, qint64 toMs,
                                 QObject *context, SamplesCallback callback)
{
    const quint64 ticket = ask(context, [callback = std::move(callback)](const std::any &result) {
        callback(std::any_cast<const Result<std::vector<HistorySample>> &>(result));
    });
    HistoryWriterWorker *worker = m_worker;
    CrossThreadCall::invoke(worker, [worker, ticket, seriesKey, fromMs, toMs] {
        worker->querySamples(ticket, seriesKey, fromMs, toMs);
    });
}

} // namespace Fatek

// The writer's moc output in its own object, not in the library's mocs_compilation.cpp beside the
// recorder's: a program that uses the writer alone (fatek-cli, the kill -9 test's child) links
// without pulling in the recorder and what it needs.
#include "moc_historywriter.cpp"
