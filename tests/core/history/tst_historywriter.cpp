// The history writer (issue 51) on its own thread against real SQLite files: samples recorded,
// flushed and read back through a second handle; a location it cannot open reported while the
// program goes on; a store locked by the real sqlite3 program reported, the samples kept and
// written once the lock is gone (recovered()); the queries (series, reduced points, samples,
// an unknown key); what is pending written by the destructor; and a writer killed with SIGKILL
// (a child process) that leaves a sound file with every value handed over more than 1.5 s before.

#include "core/history/historymessages.h"
#include "core/history/historystore.h"
#include "core/history/historywriter.h"
#include "core/qtbridge/qtmessage.h"

#include <QDateTime>
#include <QFile>
#include <QProcess>
#include <QSet>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#ifdef FATEK_HISTORY_KILL_CHILD
#include <csignal>
#endif

using namespace Fatek;

namespace {

HistorySeries makeSeries(const QString &item, const QString &label = {})
{
    HistorySeries s;
    s.source = QStringLiteral("line1");
    s.item = item;
    s.label = label;
    s.format = QStringLiteral("unsigned");
    s.heartbeatS = 10;
    return s;
}

HistoryRecord recordOf(qint64 handle, qint64 timeMs, double value)
{
    return HistoryRecord{handle,
                         HistorySample{timeMs, value, std::uint64_t(value), HistoryQuality::Good}};
}

std::vector<HistorySample> readBack(const QString &file, const QString &item)
{
    Result<std::unique_ptr<HistoryStore>> store
        = HistoryStore::open(file, HistoryStore::Mode::ReadOnly);
    if (!store) {
        qWarning("%s", english(store.error().message).c_str());
        return {};
    }
    const Result<QList<HistorySeries>> series = (*store)->series();
    for (const HistorySeries &s : *series) {
        if (s.item == item)
            return *(*store)->samples(s.id, 0, Q_INT64_C(1) << 50);
    }
    return {};
}

// Waits for the writer's flush(): what was recorded before it is committed.
bool flushed(HistoryWriter &writer)
{
    bool done = false;
    writer.flush([&done] { done = true; });
    return QTest::qWaitFor([&done] { return done; }, 20000);
}

} // namespace

class TestHistoryWriter : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void recordsAreWrittenAndReadBack()
    {
        const QString file = path("writer.db");
        HistoryWriter writer(file, HistoryRetention{});
        QSignalSpy failed(&writer, &HistoryWriter::failed);
        QCOMPARE(writer.location(), file);
        const qint64 a
            = writer.addSeries(makeSeries(QStringLiteral("1-R100"), QStringLiteral("A")));
        const qint64 b = writer.addSeries(makeSeries(QStringLiteral("1-R101")));
        QVERIFY(a != b);
        // The same key: the same handle.
        QCOMPARE(writer.addSeries(makeSeries(QStringLiteral("1-R100"), QStringLiteral("A"))), a);
        std::vector<HistoryRecord> records;
        for (qint64 t = 0; t < 100; ++t)
            records.push_back(recordOf(t % 2 ? a : b, 1000 + t, double(t)));
        writer.record(records);
        QVERIFY(flushed(writer));
        QCOMPARE(readBack(file, QStringLiteral("1-R100")).size(), std::size_t(50));
        const std::vector<HistorySample> got = readBack(file, QStringLiteral("1-R101"));
        QCOMPARE(got.size(), std::size_t(50));
        QCOMPARE(got.front(), recordOf(b, 1000, 0).sample);
        HistoryWriter::Statistics stats = writer.statistics();
        QCOMPARE(stats.written, qint64(100));
        QCOMPARE(stats.pending, qint64(0));
        QCOMPARE(stats.dropped, qint64(0));
        QVERIFY(stats.transactions >= 1);

        // A changed label reaches the store; samples written within a second without flush().
        QCOMPARE(writer.addSeries(makeSeries(QStringLiteral("1-R100"), QStringLiteral("Tank"))), a);
        writer.record({recordOf(a, 5000, 5)});
        QTRY_COMPARE_WITH_TIMEOUT(writer.statistics().written, qint64(101), 5000);
        Result<std::unique_ptr<HistoryStore>> store
            = HistoryStore::open(file, HistoryStore::Mode::ReadOnly);
        QVERIFY(store);
        QCOMPARE((*store)->series()->at(0).label, QStringLiteral("Tank"));
        QVERIFY(failed.isEmpty());
    }

    void aLocationItCannotOpenIsReported()
    {
        // Under a regular file: no folder can be made there.
        QFile plain(path("plain"));
        QVERIFY(plain.open(QIODevice::WriteOnly));
        plain.close();
        HistoryWriter writer(path("plain/history.db"), HistoryRetention{3600, 0});
        QSignalSpy failed(&writer, &HistoryWriter::failed);
        QVERIFY(failed.wait(5000));
        QVERIFY(failed.at(0).at(0).value<Message>().id == MessageId(MsgId::HistoryNoFolder));
        // The program goes on: samples are taken, kept, and the queries answer with the reason.
        const qint64 handle = writer.addSeries(makeSeries(QStringLiteral("1-R100")));
        writer.record({recordOf(handle, 1000, 1), recordOf(handle, 2000, 2)});
        QVERIFY(flushed(writer));
        QCOMPARE(writer.statistics().pending, qint64(2));
        QCOMPARE(writer.statistics().written, qint64(0));
        bool answered = false;
        writer.querySeries(this, [&](const Result<QList<HistorySeries>> &series) {
            answered = true;
            QVERIFY(!series);
            QVERIFY(series.error().message.id == MessageId(MsgId::HistoryNoFolder));
        });
        QTRY_VERIFY(answered);
        // Said once per reason, not at every retry.
        QTest::qWait(200);
        QCOMPARE(failed.size(), 1);
    }

    void lockedStoreRecoversWithItsSamples()
    {
        const QString file = path("locked.db");
        QVERIFY(HistoryStore::open(file, HistoryStore::Mode::ReadWrite));
        QProcess cli;
        cli.start(QStringLiteral("sqlite3"), {file});
        QVERIFY(cli.waitForStarted());
        cli.write("BEGIN IMMEDIATE;\nSELECT 'held';\n");
        QByteArray said;
        QTRY_VERIFY2_WITH_TIMEOUT((said += cli.readAllStandardOutput()).contains("held"),
                                  cli.readAllStandardError().constData(), 10000);

        HistoryWriter writer(file, HistoryRetention{});
        QSignalSpy failed(&writer, &HistoryWriter::failed);
        QSignalSpy recovered(&writer, &HistoryWriter::recovered);
        QVERIFY(failed.wait(10000));
        QVERIFY(failed.at(0).at(0).value<Message>().id == MessageId(MsgId::HistoryLocked));
        const qint64 handle = writer.addSeries(makeSeries(QStringLiteral("1-R100")));
        for (qint64 t = 0; t < 10; ++t)
            writer.record({recordOf(handle, 1000 * t, double(t))});
        QTRY_COMPARE_WITH_TIMEOUT(writer.statistics().pending, qint64(10), 5000);
        QCOMPARE(writer.statistics().written, qint64(0));

        cli.closeWriteChannel();
        QVERIFY(cli.waitForFinished());
        // Tried again within 5 s (and a second).
        QVERIFY(recovered.wait(10000));
        QVERIFY(flushed(writer));
        QCOMPARE(readBack(file, QStringLiteral("1-R100")).size(), std::size_t(10));
        QCOMPARE(writer.statistics().written, qint64(10));
        QCOMPARE(writer.statistics().pending, qint64(0));
        QCOMPARE(failed.size(), 1);
    }

    void queriesAnswerInTheCallersThread()
    {
        const QString file = path("queries.db");
        HistoryWriter writer(file, HistoryRetention{});
        const qint64 handle
            = writer.addSeries(makeSeries(QStringLiteral("1-R100"), QStringLiteral("Tank")));
        std::vector<HistoryRecord> records;
        for (qint64 t = 0; t < 1000; ++t)
            records.push_back(recordOf(handle, 1'000'000 + t * 1000, double(t % 10)));
        // Queried at once: what is pending is written before the answer.
        writer.record(records);

        bool answered = false;
        writer.querySeries(this, [&](const Result<QList<HistorySeries>> &series) {
            answered = true;
            QVERIFY(QThread::currentThread() == thread());
            QVERIFY(series);
            QCOMPARE(series->size(), 1);
            QCOMPARE(series->at(0).key(), QStringLiteral("line1/1-R100"));
            QCOMPARE(series->at(0).label, QStringLiteral("Tank"));
        });
        QTRY_VERIFY(answered);

        answered = false;
        writer.queryPoints(QStringLiteral("line1/1-R100"), 1'000'000, 2'000'000, 10, this,
                           [&](const Result<std::vector<HistoryPoint>> &points) {
                               answered = true;
                               QVERIFY(QThread::currentThread() == thread());
                               QVERIFY(points);
                               // Ten columns, each first, max, min, last; no gaps.
                               QVERIFY(points->size() <= 40 && points->size() >= 10);
                               QCOMPARE(points->front(), (HistoryPoint{1'000'000, 0, false}));
                               QCOMPARE(points->back(), (HistoryPoint{1'999'000, 9, false}));
                           });
        QTRY_VERIFY(answered);

        answered = false;
        writer.querySamples(QStringLiteral("line1/1-R100"), 1'500'000, 1'510'000, this,
                            [&](const Result<std::vector<HistorySample>> &samples) {
                                answered = true;
                                QVERIFY(samples);
                                // The one before the range and ten in it.
                                QCOMPARE(samples->size(), std::size_t(11));
                                QCOMPARE(samples->front().timeMs, qint64(1'499'000));
                            });
        QTRY_VERIFY(answered);

        answered = false;
        writer.querySamples(QStringLiteral("line1/1-R999"), 0, 1, this,
                            [&](const Result<std::vector<HistorySample>> &samples) {
                                answered = true;
                                QVERIFY(!samples);
                                QVERIFY(samples.error().message.id
                                        == MessageId(MsgId::HistoryUnknownSeries));
                                QVERIFY(QString::fromStdString(english(samples.error().message))
                                            .contains(QLatin1String("line1/1-R999")));
                            });
        QTRY_VERIFY(answered);
        answered = false;
        writer.queryPoints(QStringLiteral("nothing"), 0, 1, 10, this,
                           [&](const Result<std::vector<HistoryPoint>> &points) {
                               answered = true;
                               QVERIFY(!points);
                           });
        QTRY_VERIFY(answered);

        // A context gone before the answer: no call.
        bool called = false;
        auto *context = new QObject;
        writer.querySeries(context, [&](const Result<QList<HistorySeries>> &) { called = true; });
        delete context;
        QVERIFY(flushed(writer));
        QTest::qWait(100);
        QVERIFY(!called);
    }

    void destructorWritesWhatIsPending()
    {
        const QString file = path("pending.db");
        {
            HistoryWriter writer(file, HistoryRetention{});
            const qint64 handle = writer.addSeries(makeSeries(QStringLiteral("1-R100")));
            for (qint64 t = 0; t < 500; ++t)
                writer.record({recordOf(handle, t, double(t))});
            // No flush, no wait: gone at once.
        }
        QCOMPARE(readBack(file, QStringLiteral("1-R100")).size(), std::size_t(500));
    }

    void killedWriterKeepsWhatItWasHanded()
    {
#ifndef FATEK_HISTORY_KILL_CHILD
        QSKIP("no kill -9 child on this platform (SIGKILL and its helper are Linux-only)");
#else
        const QString file = path("killed.db");
        QProcess child;
        child.setProcessChannelMode(QProcess::SeparateChannels);
        child.start(QStringLiteral(FATEK_HISTORY_KILL_CHILD), {file});
        QVERIFY(child.waitForStarted());
        QByteArray said;
        QTRY_VERIFY_WITH_TIMEOUT((said += child.readAllStandardOutput()).count('\n') >= 5, 20000);
        QTest::qWait(3000);
        const qint64 killedMs = QDateTime::currentMSecsSinceEpoch();
        ::kill(static_cast<pid_t>(child.processId()), SIGKILL);
        QVERIFY(child.waitForFinished());
        QCOMPARE(child.exitStatus(), QProcess::CrashExit);
        said += child.readAllStandardOutput();
        QVERIFY2(child.readAllStandardError().isEmpty(), "the child reported a failure");

        // The file is sound after the kill...
        QProcess check;
        check.start(QStringLiteral("sqlite3"), {file, QStringLiteral("PRAGMA integrity_check;")});
        QVERIFY(check.waitForFinished());
        QCOMPARE(check.readAllStandardOutput().trimmed(), QByteArray("ok"));
        // ... and has every value handed over more than 1.5 s before it.
        const std::vector<HistorySample> kept = readBack(file, QStringLiteral("1-R100"));
        QSet<qint64> times;
        for (const HistorySample &s : kept)
            times.insert(s.timeMs);
        int handed = 0;
        int old = 0;
        for (const QByteArray &line : said.trimmed().split('\n')) {
            const qint64 t = line.toLongLong();
            ++handed;
            if (t >= killedMs - 1500)
                continue;
            ++old;
            QVERIFY2(times.contains(t), qPrintable(QStringLiteral("%1 missing").arg(t)));
        }
        qDebug("kill -9: %d values handed over, %d of them 1.5 s before the kill, %zu in the file",
               handed, old, kept.size());
        QVERIFY(old >= 20);
        QVERIFY(Result<std::unique_ptr<HistoryStore>>(
            HistoryStore::open(file, HistoryStore::Mode::ReadWrite)));
#endif
    }
};

QTEST_GUILESS_MAIN(TestHistoryWriter)

#include "tst_historywriter.moc"
