// Figure 9 (issue 51): what keeping the history costs. Recording: 10,000 items whose every value
// changes once a second, handed to a HistoryRecorder as a plant connection hands them and written
// by a HistoryWriter (its own thread, one transaction a second) for 60 s (--quick: 6 s): the
// process's CPU (recorder, writer and the feeding of the batches) against one core, the writer's
// queue at each second (it must not grow), and the store's bytes per value kept. Looking back:
// one day of one item at 1 s (86,400 values) read and reduced to a 1,000-pixel trend. Both
// against an SQLite file and a PostgreSQL server started for the figure (initdb + pg_ctl in a
// temporary folder, as the tests start theirs), when this build has PostgreSQL.
#include "bench.h"

#include "core/history/historyrecorder.h"
#include "core/history/historyreducer.h"
#include "core/history/historystore.h"
#include "core/history/historywriter.h"
#ifdef FATEK_BENCH_POSTGRES
#include "postgresserver.h"
#endif

#include <QCoreApplication>
#include <QDateTime>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTemporaryDir>
#include <QTimer>

#include <sys/resource.h>

#include <cmath>
#include <numbers>

namespace Fatek::Bench {

namespace {

constexpr int Items = 10000;
constexpr int RegistersPerStation = 3840; // R0..R3839 of an FBs
constexpr int DaySamples = 86400;
constexpr int TrendPixels = 1000;

qint64 cpuNs()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto ns = [](const timeval &t) {
        return qint64(t.tv_sec) * 1000000000 + qint64(t.tv_usec) * 1000;
    };
    return ns(usage.ru_utime) + ns(usage.ru_stime);
}

struct Recording
{
    double cpuPercent = 0;
    qint64 maxPending = 0;
    qint64 lastPending = 0;
    qint64 written = 0;
    qint64 expected = 0;
    double bytesPerValue = 0;
    bool ok = false;
};

Recording record(const QString &location, int seconds)
{
    Recording r;
    QList<WatchedItem> items;
    items.reserve(Items);
    for (int i = 0; i < Items; ++i) {
        WatchItemSpec spec;
        spec.address
            = *Address::parse(QStringLiteral("R%1").arg(i % RegistersPerStation).toStdString());
        spec.station = static_cast<quint8>(1 + i / RegistersPerStation);
        spec.format = DisplayFormat::Unsigned;
        spec.history = HistorySetting{};
        items.append(WatchedItem{0, spec, 1000});
    }
    HistoryWriter writer(location, {});
    {
        HistoryRecorder recorder(QStringLiteral("bench"), &writer);
        // The recorder numbers its items from a block of fresh keys (as the alarm engine does).
        const std::uint64_t firstKey = WatchedItem::newKey() + 1;
        recorder.setItems(items);
        QList<WatchItemValue> batch(Items);
        for (int i = 0; i < Items; ++i) {
            WatchItemValue &v = batch[i];
            v.key = firstKey + static_cast<std::uint64_t>(i);
            v.words = {0};
            v.hasValue = true;
            v.quality = ValueQuality::Good;
        }
        int second = 0;
        const qint64 cpuBefore = cpuNs();
        QElapsedTimer wall;
        wall.start();
        QEventLoop loop;
        QTimer tick;
        tick.setInterval(1000);
        QObject::connect(&tick, &QTimer::timeout, &loop, [&] {
            if (second == seconds) {
                loop.quit();
                return;
            }
            const QDateTime now = QDateTime::currentDateTimeUtc();
            for (int i = 0; i < Items; ++i) {
                // A different value every second, for every item.
                const auto raw = static_cast<std::uint32_t>((i + second * 7) % 60000);
                batch[i].words[0] = raw;
                batch[i].raw = raw;
                batch[i].time = now;
            }
            recorder.plantValues(batch);
            const qint64 pending = writer.statistics().pending;
            r.maxPending = std::max(r.maxPending, pending);
            r.lastPending = pending;
            ++second;
        });
        tick.start();
        loop.exec();
        const double cpu = static_cast<double>(cpuNs() - cpuBefore);
        r.cpuPercent = cpu / static_cast<double>(wall.nsecsElapsed()) * 100;
        r.expected = qint64(seconds) * Items;
    }
    bool flushed = false;
    writer.flush([&flushed] { flushed = true; });
    QElapsedTimer waited;
    waited.start();
    while (!flushed && waited.elapsed() < 60000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 100);
    r.written = writer.statistics().written;
    Result<std::unique_ptr<HistoryStore>> store
        = HistoryStore::open(location, HistoryStore::Mode::ReadOnly);
    if (store) {
        const Result<qint64> bytes = (*store)->sizeBytes();
        const Result<qint64> count = (*store)->sampleCount();
        if (bytes && count && *count > 0)
            r.bytesPerValue = static_cast<double>(*bytes) / static_cast<double>(*count);
    }
    // Every value kept (plus the Off samples of the recorder's end), no queue left.
    r.ok = flushed && r.written >= r.expected && store;
    return r;
}

// One day of one item at 1 s, then the time to read and reduce it for a 1,000-pixel trend.
double lookBackMs(const QString &location, bool *ok)
{
    *ok = false;
    Result<std::unique_ptr<HistoryStore>> store
        = HistoryStore::open(location, HistoryStore::Mode::ReadWrite);
    if (!store)
        return 0;
    const Result<qint64> id
        = (*store)->seriesId({0, QStringLiteral("bench"), QStringLiteral("9-R0"),
                              QStringLiteral("day"), QStringLiteral("signed"), 600});
    if (!id)
        return 0;
    const qint64 start = Q_INT64_C(1796601600000); // 2026-12-07T00:00:00Z
    std::vector<HistoryRecord> records;
    records.reserve(DaySamples);
    for (int s = 0; s < DaySamples; ++s) {
        HistorySample sample;
        sample.timeMs = start + qint64(s) * 1000;
        sample.value = std::round(1000 * std::sin(2 * std::numbers::pi * s / 3600.0));
        sample.raw = static_cast<std::uint64_t>(static_cast<qint64>(sample.value)) & 0xffff;
        records.push_back({*id, sample});
    }
    if (!(*store)->append(records))
        return 0;
    double best = 1e9;
    std::size_t points = 0;
    // Three runs, the best: the first pays for the cold page cache of a file just written.
    for (int run = 0; run < 3; ++run) {
        QElapsedTimer clock;
        clock.start();
        const Result<std::vector<HistorySample>> samples
            = (*store)->samples(*id, start, start + qint64(DaySamples) * 1000);
        if (!samples)
            return 0;
        const std::vector<HistoryPoint> reduced
            = HistoryReducer::reduce(*samples, start, start + qint64(DaySamples) * 1000,
                                     TrendPixels, History::maxSilenceMs(600));
        best = std::min(best, static_cast<double>(clock.nsecsElapsed()) / 1e6);
        points = reduced.size();
        *ok = samples->size() == DaySamples && points > 0 && points <= 4 * TrendPixels;
    }
    return best;
}

void reportStore(const QString &name, const QString &key, const QString &location, int seconds,
                 Report &report)
{
    const Recording r = record(location, seconds);
    report.row(QStringLiteral("history %1: 10,000 items changing every second, %2 s")
                   .arg(name)
                   .arg(seconds),
               QStringLiteral("%1% of one core").arg(fmt(r.cpuPercent, 1)),
               QStringLiteral("queue at most %1 values (last %2); %3 of %4 values written; "
                              "%5 bytes per value")
                   .arg(r.maxPending)
                   .arg(r.lastPending)
                   .arg(r.written)
                   .arg(r.expected)
                   .arg(fmt(r.bytesPerValue, 1)),
               {}, QStringLiteral("<= 10%"));
    // The queue holds at most two seconds of values (one being written, one coming): no growth.
    report.result(QStringLiteral("history_%1_record_cpu_percent").arg(key), r.cpuPercent,
                  QStringLiteral("<=10"), r.ok && r.cpuPercent <= 10 && r.maxPending <= 2 * Items);
    report.result(QStringLiteral("history_%1_bytes_per_value").arg(key), r.bytesPerValue,
                  QStringLiteral("report"), r.ok);
    bool ok = false;
    const double ms = lookBackMs(location, &ok);
    report.row(QStringLiteral("history %1: a day of one item at 1 s read and reduced to 1,000 px")
                   .arg(name),
               QStringLiteral("%1 ms").arg(fmt(ms, 1)), QStringLiteral("86,400 values"), {},
               QStringLiteral("<= 100 ms"));
    report.result(QStringLiteral("history_%1_day_query_ms").arg(key), ms, QStringLiteral("<=100"),
                  ok && ms <= 100);
}

} // namespace

void runHistory(const Options &options, Report &report)
{
    const int seconds = options.quick ? 6 : 60;
    QTemporaryDir dir;
    reportStore(QStringLiteral("SQLite"), QStringLiteral("sqlite"),
                dir.filePath(QStringLiteral("history.sqlite")), seconds, report);
#ifdef FATEK_BENCH_POSTGRES
    TestUtil::PostgresServer server;
    QString error;
    if (!server.start(&error) || !server.createDatabase(QStringLiteral("bench"), &error)) {
        std::fprintf(stderr, "figure 9: no PostgreSQL server: %s\n", qPrintable(error));
        report.result(QStringLiteral("history_postgres_record_cpu_percent"), 0,
                      QStringLiteral("<=10"), false);
        return;
    }
    reportStore(QStringLiteral("PostgreSQL"), QStringLiteral("postgres"),
                server.url(QStringLiteral("bench")), seconds, report);
#endif
}

} // namespace Fatek::Bench
