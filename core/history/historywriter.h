#pragma once

#include "historysink.h"
#include "historystore.h"
#include "historytypes.h"

#include "core/protocol/message.h"
#include "core/protocol/result.h"

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QThread>

#include <any>
#include <atomic>
#include <functional>

namespace Fatek {

class HistoryWriterWorker;

// The history store of the studio and the gateway, on a thread of its own so that a slow disk or
// database never stalls the values or the UI: the HistoryStore lives there and is touched there
// only; every hand-over is a CrossThreadCall. Samples are written once a second, in one
// transaction (a kill -9 loses at most the last second). A store that cannot be opened or written
// is reported (failed()) and the program keeps polling: samples are kept (up to MaxPending, the
// oldest dropped beyond, counted) and tried again every 5 s. Retention is applied at open and
// every minute. Queries (the trend, an export) run there too, after what is pending is written.
class HistoryWriter : public QObject, public HistorySink
{
    Q_OBJECT

public:
    static constexpr qsizetype MaxPending = 2'000'000;

    struct Statistics
    {
        qint64 written = 0;      // samples committed
        qint64 pending = 0;      // samples waiting for the next transaction
        qint64 dropped = 0;      // samples lost beyond MaxPending while the store failed
        qint64 transactions = 0; // commits
        qint64 retained = 0;     // samples removed by retention
    };

    using SeriesCallback = std::function<void(const Result<QList<HistorySeries>> &)>;
    using PointsCallback = std::function<void(const Result<std::vector<HistoryPoint>> &)>;
    using SamplesCallback = std::function<void(const Result<std::vector<HistorySample>> &)>;

    // Opens (or creates) the store on the writer's thread at once; failed() says if it cannot.
    HistoryWriter(const QString &location, const HistoryRetention &retention,
                  QObject *parent = nullptr);
    // Writes what is pending, closes the store and joins the thread.
    ~HistoryWriter() override;

    QString location() const { return m_location; }
    // Thread-safe: the counters as of the last transaction.
    Statistics statistics() const;

    // HistorySink, in this object's thread.
    qint64 addSeries(const HistorySeries &series) override;
    void record(std::vector<HistoryRecord> records) override;

    // Writes what is pending now (tests, a clean stop); `done` runs in this object's thread.
    void flush(std::function<void()> done = {});

    // Queries by series key ("line1/1-R100"); an unknown key is an error naming it. Callbacks run
    // in `context`'s thread, unless `context` is gone by then or this writer is destroyed first.
    void querySeries(QObject *context, SeriesCallback callback);
    void queryPoints(const QString &seriesKey, qint64 fromMs, qint64 toMs, int buckets,
                     QObject *context, PointsCallback callback);
    void querySamples(const QString &seriesKey, qint64 fromMs, qint64 toMs, QObject *context,
                      SamplesCallback callback);

Q_SIGNALS:
    // The store cannot be opened or written (said once per distinct reason).
    void failed(const Fatek::Message &reason);
    // Written again after a failure.
    void recovered();

private:
    friend class HistoryWriterWorker;

    // A query's answer on its way back: kept in this object's thread with its ticket until the
    // worker answers (the callback never travels to the store's thread).
    struct Query
    {
        QPointer<QObject> context;
        std::function<void(const std::any &)> deliver;
    };
    quint64 ask(QObject *context, std::function<void(const std::any &)> deliver);
    // Called by the worker, through a CrossThreadCall, in this object's thread.
    void answered(quint64 ticket, const std::any &result);

    QString m_location;
    QThread m_thread;
    HistoryWriterWorker *m_worker = nullptr;
    QHash<QString, qint64> m_handles; // series key -> handle
    QList<HistorySeries> m_series;    // by handle - 1
    quint64 m_nextTicket = 1;
    QHash<quint64, Query> m_queries;
    // Updated by the worker after each transaction.
    std::atomic<qint64> m_written{0};
    std::atomic<qint64> m_pending{0};
    std::atomic<qint64> m_dropped{0};
    std::atomic<qint64> m_transactions{0};
    std::atomic<qint64> m_retained{0};
};

} // namespace Fatek
