// The history store (issue 51) on the real SQLite library and files: samples back as written (a
// value without a number, raw words with the top bit set, every quality), the sample before a
// range, a replaced sample, stable series ids with updated labels; the files it refuses (another
// program's database, a newer format, damaged, missing, locked by the real sqlite3 program) and
// leaves as they were; retention by age and by size (the file really shrinks); and a PostgreSQL
// URL in a build without libpq.

#include "core/history/historymessages.h"
#include "core/history/historyreducer.h"
#include "core/history/historystore.h"
#include "core/history/sqlitehistorystore.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>

using namespace Fatek;

namespace {

QByteArray fileBytes(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

HistorySeries makeSeries(const QString &item, const QString &label = {})
{
    HistorySeries s;
    s.source = QStringLiteral("line1");
    s.item = item;
    s.label = label;
    s.format = QStringLiteral("signed");
    return s;
}

HistorySample sample(qint64 timeMs, double value, std::uint64_t raw = 0,
                     HistoryQuality quality = HistoryQuality::Good)
{
    return HistorySample{timeMs, value, raw, quality};
}

// Runs the sqlite3 program on `file` with `sql`; its exit code.
int sqliteCli(const QString &file, const QString &sql)
{
    QProcess cli;
    cli.start(QStringLiteral("sqlite3"), {file, sql});
    if (!cli.waitForFinished())
        return -1;
    return cli.exitCode();
}

} // namespace

class TestHistoryStore : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }

    std::unique_ptr<HistoryStore> openOk(const QString &file,
                                         HistoryStore::Mode mode = HistoryStore::Mode::ReadWrite)
    {
        Result<std::unique_ptr<HistoryStore>> store = HistoryStore::open(file, mode);
        if (!store)
            qWarning("%s", english(store.error().message).c_str());
        return store ? std::move(store).value() : nullptr;
    }

    static MessageId idOf(const Result<std::unique_ptr<HistoryStore>> &store)
    {
        return store.error().message.id;
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void samplesComeBackAsWritten()
    {
        const QString file = path("roundtrip.db");
        auto store = openOk(file);
        QVERIFY(store);
        QCOMPARE(store->location(), file);
        const qint64 id = *store->seriesId(makeSeries(QStringLiteral("1-R100")));
        const std::uint64_t topBit = std::uint64_t(1) << 63;
        const std::vector<HistorySample> written{
            sample(1000, 1.5, 15),
            sample(2000, std::numeric_limits<double>::quiet_NaN(), topBit | 0x1234,
                   HistoryQuality::Late),
            sample(3000, std::numeric_limits<double>::quiet_NaN(), 0, HistoryQuality::Stale),
            sample(4000, -2.25, std::numeric_limits<std::uint64_t>::max(), HistoryQuality::Error),
            sample(5000, std::numeric_limits<double>::quiet_NaN(), 7, HistoryQuality::Off),
            sample(6000, 1e300, topBit, HistoryQuality::Good),
        };
        std::vector<HistoryRecord> records;
        for (const HistorySample &s : written)
            records.push_back({id, s});
        QVERIFY(store->append(records));
        QCOMPARE(*store->sampleCount(), qint64(written.size()));
        QCOMPARE(*store->samples(id, 0, 10000), written);
        // NaN is kept as NULL in the table, the raw words bit for bit.
        store.reset();
        QProcess cli;
        cli.start(QStringLiteral("sqlite3"),
                  {file, QStringLiteral("SELECT time_ms, value IS NULL, raw, quality FROM samples "
                                        "WHERE time_ms IN (2000, 4000) ORDER BY time_ms;")});
        QVERIFY(cli.waitForFinished());
        QCOMPARE(cli.readAllStandardOutput(), QByteArray("2000|1|-9223372036854771148|1\n"
                                                         "4000|0|-1|3\n"));
        store = openOk(file, HistoryStore::Mode::ReadOnly);
        QVERIFY(store);
        QCOMPARE(*store->samples(id, 0, 10000), written);
        QCOMPARE(History::qualityName(HistoryQuality::Late), QStringLiteral("late"));
        QCOMPARE(History::qualityFromName(QStringLiteral("off")), HistoryQuality::Off);
        QVERIFY(!History::qualityFromName(QStringLiteral("bad")));
    }

    void rangeStartsWithTheSampleBefore()
    {
        auto store = openOk(path("range.db"));
        QVERIFY(store);
        const qint64 a = *store->seriesId(makeSeries(QStringLiteral("1-R100")));
        const qint64 b = *store->seriesId(makeSeries(QStringLiteral("1-R101")));
        std::vector<HistoryRecord> records;
        for (qint64 t = 0; t < 10; ++t) {
            records.push_back({a, sample(t * 100, double(t))});
            records.push_back({b, sample(t * 100 + 50, double(-t))});
        }
        QVERIFY(store->append(records));
        // [350, 700): the one at 300 enters, 700 is outside.
        const std::vector<HistorySample> got = *store->samples(a, 350, 700);
        QCOMPARE(got, (std::vector<HistorySample>{sample(300, 3), sample(400, 4), sample(500, 5),
                                                  sample(600, 6)}));
        // From an exact sample time: the one before it enters, the one at fromMs is in.
        QCOMPARE(store->samples(a, 400, 500)->size(), std::size_t(2));
        QCOMPARE(store->samples(a, 400, 500)->front(), sample(300, 3));
        // Nothing before the first sample; a limit counts the entering one.
        QCOMPARE(*store->samples(a, 0, 250),
                 (std::vector<HistorySample>{sample(0, 0), sample(100, 1), sample(200, 2)}));
        QCOMPARE(store->samples(a, 350, 10000, 3)->size(), std::size_t(3));
        QCOMPARE(store->samples(a, 350, 10000, 3)->back(), sample(500, 5));
        // Another series' samples never mix in; a range after the last sample has the last.
        QCOMPARE(*store->samples(b, 5000, 6000), (std::vector<HistorySample>{sample(950, -9)}));
        QVERIFY(store->samples(4711, 0, 1000)->empty());
    }

    void sameTimeReplaces()
    {
        auto store = openOk(path("replace.db"));
        QVERIFY(store);
        const qint64 id = *store->seriesId(makeSeries(QStringLiteral("1-D0")));
        QVERIFY(store->append({{id, sample(1000, 1)}, {id, sample(2000, 2)}}));
        QVERIFY(store->append({{id, sample(1000, 10, 10, HistoryQuality::Late)}}));
        QCOMPARE(*store->samples(id, 0, 5000),
                 (std::vector<HistorySample>{sample(1000, 10, 10, HistoryQuality::Late),
                                             sample(2000, 2)}));
        QCOMPARE(*store->sampleCount(), qint64(2));
    }

    void seriesIdsAreStableAndLabelsUpdated()
    {
        const QString file = path("series.db");
        qint64 first = 0;
        qint64 second = 0;
        {
            auto store = openOk(file);
            QVERIFY(store);
            first = *store->seriesId(makeSeries(QStringLiteral("1-R100"), QStringLiteral("Tank")));
            second = *store->seriesId(makeSeries(QStringLiteral("1-R101")));
            QVERIFY(first != second);
            QCOMPARE(*store->seriesId(makeSeries(QStringLiteral("1-R100"), QStringLiteral("Tank"))),
                     first);
            HistorySeries other = makeSeries(QStringLiteral("1-R100"));
            other.source = QStringLiteral("line2");
            QVERIFY(*store->seriesId(other) != first);
        }
        auto store = openOk(file);
        QVERIFY(store);
        HistorySeries renamed = makeSeries(QStringLiteral("1-R100"), QStringLiteral("Tank level"));
        renamed.format = QStringLiteral("float");
        renamed.heartbeatS = 60;
        renamed.id = 999; // ignored
        QCOMPARE(*store->seriesId(renamed), first);
        const QList<HistorySeries> all = *store->series();
        QCOMPARE(all.size(), 3);
        // Ordered by source and item, with their ids.
        renamed.id = first;
        QCOMPARE(all.at(0), renamed);
        QCOMPARE(all.at(1).id, second);
        QCOMPARE(all.at(2).source, QStringLiteral("line2"));
        QCOMPARE(all.at(0).key(), QStringLiteral("line1/1-R100"));
        // To read: known series by their id, nothing made.
        auto reader = openOk(file, HistoryStore::Mode::ReadOnly);
        QVERIFY(reader);
        QCOMPARE(*reader->seriesId(renamed), first);
        const Result<qint64> unknown = reader->seriesId(makeSeries(QStringLiteral("1-R999")));
        QVERIFY(!unknown);
        QVERIFY(unknown.error().message.id == MessageId(MsgId::HistoryUnknownSeries));
        const Status refused = reader->append({{first, sample(1, 1)}});
        QVERIFY(!refused);
        QVERIFY(refused.error().message.id == MessageId(MsgId::HistoryReadOnly));
        QCOMPARE(reader->series()->size(), 3);
    }

    void anotherProgramsDatabaseIsLeftAlone()
    {
        const QString file = path("other.db");
        QCOMPARE(sqliteCli(file, QStringLiteral("CREATE TABLE samples (a); "
                                                "INSERT INTO samples VALUES (1);")),
                 0);
        const QByteArray before = fileBytes(file);
        QVERIFY(!before.isEmpty());
        for (auto mode : {HistoryStore::Mode::ReadWrite, HistoryStore::Mode::ReadOnly}) {
            Result<std::unique_ptr<HistoryStore>> store = HistoryStore::open(file, mode);
            QVERIFY(!store);
            QVERIFY(idOf(store) == MessageId(MsgId::HistoryNotHistory));
        }
        QCOMPARE(fileBytes(file), before);
        QVERIFY(!QFile::exists(file + QLatin1String("-wal")));
        // An empty SQLite file holds no history to read, and becomes one to write.
        const QString empty = path("empty.db");
        QVERIFY(QFile(empty).open(QIODevice::WriteOnly));
        QVERIFY(!HistoryStore::open(empty, HistoryStore::Mode::ReadOnly));
        QVERIFY(openOk(empty));
        QVERIFY(openOk(empty, HistoryStore::Mode::ReadOnly));
    }

    void newerFormatIsRefused()
    {
        const QString file = path("newer.db");
        QVERIFY(openOk(file));
        QCOMPARE(sqliteCli(file, QStringLiteral("PRAGMA user_version=7;")), 0);
        const QByteArray before = fileBytes(file);
        Result<std::unique_ptr<HistoryStore>> store
            = HistoryStore::open(file, HistoryStore::Mode::ReadWrite);
        QVERIFY(!store);
        QVERIFY(idOf(store) == MessageId(MsgId::HistoryNewer));
        QCOMPARE(QString::fromStdString(english(store.error().message)),
                 QStringLiteral("The history store %1 has format 7, newer than this program reads "
                                "(1); it was left as it is.")
                     .arg(QDir::toNativeSeparators(file)));
        QCOMPARE(fileBytes(file), before);
    }

    void damagedFileIsRefusedWithSqlitesReason()
    {
        const QString file = path("damaged.db");
        QByteArray garbage;
        for (int i = 0; i < 8192; ++i)
            garbage.append(static_cast<char>((i * 7919) % 251));
        {
            QFile out(file);
            QVERIFY(out.open(QIODevice::WriteOnly));
            out.write(garbage);
        }
        for (auto mode : {HistoryStore::Mode::ReadWrite, HistoryStore::Mode::ReadOnly}) {
            Result<std::unique_ptr<HistoryStore>> store = HistoryStore::open(file, mode);
            QVERIFY(!store);
            QVERIFY(idOf(store) == MessageId(MsgId::HistoryOpenFailed));
            const QString text = QString::fromStdString(english(store.error().message));
            QVERIFY2(text.contains(QLatin1String("file is not a database")), qPrintable(text));
            QVERIFY2(text.contains(QLatin1String("damaged.db")), qPrintable(text));
        }
        QCOMPARE(fileBytes(file), garbage);
    }

    void missingFileToRead()
    {
        Result<std::unique_ptr<HistoryStore>> store
            = HistoryStore::open(path("nothing-here.db"), HistoryStore::Mode::ReadOnly);
        QVERIFY(!store);
        QVERIFY(idOf(store) == MessageId(MsgId::HistoryMissing));
        QVERIFY(!QFile::exists(path("nothing-here.db")));
        // To write, the folder is made.
        QVERIFY(openOk(path("a/b/new.db")));
        QVERIFY(QFile::exists(path("a/b/new.db")));
        // Under a regular file no folder can be made.
        store = HistoryStore::open(path("damaged.db/x.db"), HistoryStore::Mode::ReadWrite);
        QVERIFY(!store);
        QVERIFY(idOf(store) == MessageId(MsgId::HistoryNoFolder));
    }

    void lockedByAnotherProgram()
    {
        const QString file = path("locked.db");
        auto early = openOk(file);
        QVERIFY(early);
        const qint64 id = *early->seriesId(makeSeries(QStringLiteral("1-R100")));
        // The real sqlite3 program holds the write lock until its input ends.
        QProcess cli;
        cli.start(QStringLiteral("sqlite3"), {file});
        QVERIFY(cli.waitForStarted());
        cli.write("BEGIN IMMEDIATE;\nSELECT 'held';\n");
        QByteArray said;
        QTRY_VERIFY2_WITH_TIMEOUT((said += cli.readAllStandardOutput()).contains("held"),
                                  cli.readAllStandardError().constData(), 10000);

        Result<std::unique_ptr<HistoryStore>> store
            = HistoryStore::open(file, HistoryStore::Mode::ReadWrite);
        QVERIFY(!store);
        QVERIFY(idOf(store) == MessageId(MsgId::HistoryLocked));
        const Status appended = early->append({{id, sample(1, 1)}});
        QVERIFY(!appended);
        QVERIFY(appended.error().message.id == MessageId(MsgId::HistoryLocked));
        QVERIFY(!early->seriesId(makeSeries(QStringLiteral("1-R200"))));
        // Readers never wait for the writer (WAL).
        auto reader = openOk(file, HistoryStore::Mode::ReadOnly);
        QVERIFY(reader);
        QVERIFY(reader->samples(id, 0, 10));

        cli.closeWriteChannel();
        QVERIFY(cli.waitForFinished());
        QVERIFY(early->append({{id, sample(1, 1)}}));
        QCOMPARE(*early->samples(id, 0, 10), std::vector<HistorySample>{sample(1, 1)});
    }

    void retentionByAge()
    {
        auto store = openOk(path("age.db"));
        QVERIFY(store);
        const qint64 a = *store->seriesId(makeSeries(QStringLiteral("1-R100")));
        const qint64 b = *store->seriesId(makeSeries(QStringLiteral("1-R101")));
        const qint64 now = 10'000'000;
        std::vector<HistoryRecord> records;
        for (qint64 t = 0; t < 10'000; ++t)
            records.push_back({t % 2 ? a : b, sample(t * 1000, double(t))});
        QVERIFY(store->append(records));
        // Kept: the last hour (3,600 samples at or after now - 3,600 s).
        const Result<HistoryRetentionOutcome> outcome
            = store->applyRetention(HistoryRetention{3600, 0}, now);
        QVERIFY(outcome);
        QCOMPARE(outcome->samplesRemoved, qint64(10'000 - 3600));
        QCOMPARE(*store->sampleCount(), qint64(3600));
        QCOMPARE(store->samples(a, 0, now)->front().timeMs, qint64(6'401'000));
        QCOMPARE(store->samples(b, 0, now)->front().timeMs, qint64(6'400'000));
        // Again: nothing more to do; no limit: nothing at all.
        QCOMPARE(store->applyRetention(HistoryRetention{3600, 0}, now)->samplesRemoved, qint64(0));
        QCOMPARE(store->applyRetention(HistoryRetention{}, now * 10)->samplesRemoved, qint64(0));
    }

    void retentionBySizeShrinksTheFile()
    {
        const QString file = path("size.db");
        auto store = openOk(file);
        QVERIFY(store);
        std::vector<qint64> ids;
        for (int i = 0; i < 4; ++i)
            ids.push_back(*store->seriesId(makeSeries(QStringLiteral("1-R%1").arg(i))));
        // 4 series x 50,000 samples, one a second.
        QElapsedTimer timer;
        qint64 appendMs = 0;
        for (qint64 chunk = 0; chunk < 20; ++chunk) {
            std::vector<HistoryRecord> records;
            for (qint64 t = chunk * 2500; t < (chunk + 1) * 2500; ++t) {
                for (qint64 id : ids)
                    records.push_back(
                        {id, sample(t * 1000, double(t % 977) / 3.0, std::uint64_t(t))});
            }
            timer.start();
            QVERIFY(store->append(records));
            appendMs += timer.elapsed();
        }
        qDebug("append: 200,000 samples in 20 transactions of 10,000: %lld ms (%.1f ms each)",
               appendMs, double(appendMs) / 20);
        const qint64 before = *store->sizeBytes();
        QVERIFY2(before > 3'000'000, qPrintable(QString::number(before)));
        const qint64 limit = before / 3;
        timer.start();
        const Result<HistoryRetentionOutcome> outcome
            = store->applyRetention(HistoryRetention{0, limit}, 0);
        qDebug("size retention %lld -> %lld bytes (limit %lld), %lld samples removed: %lld ms",
               outcome ? outcome->bytesBefore : 0, outcome ? outcome->bytesAfter : 0, limit,
               outcome ? outcome->samplesRemoved : 0, timer.elapsed());
        QVERIFY(outcome);
        QVERIFY(outcome->samplesRemoved > 0);
        QCOMPARE(outcome->bytesBefore, before);
        QVERIFY2(outcome->bytesAfter <= limit, qPrintable(QString::number(outcome->bytesAfter)));
        // The file itself, its log truncated: really given back to the file system.
        QVERIFY(QFileInfo(file).size() + QFileInfo(file + QLatin1String("-wal")).size() <= limit);
        QCOMPARE(*store->sizeBytes(), outcome->bytesAfter);
        // Oldest first across the series: what is left is the newest of each, alike.
        const qint64 left = *store->sampleCount();
        QCOMPARE(left, 200'000 - outcome->samplesRemoved);
        QVERIFY(left > 0);
        qint64 firstKept = -1;
        for (qint64 id : ids) {
            const std::vector<HistorySample> kept = *store->samples(id, 0, 1LL << 40);
            QCOMPARE(kept.back().timeMs, qint64(49'999'000));
            if (firstKept < 0)
                firstKept = kept.front().timeMs;
            QCOMPARE(kept.front().timeMs, firstKept);
        }
        // Fits now: nothing more goes.
        QCOMPARE(store->applyRetention(HistoryRetention{0, limit}, 0)->samplesRemoved, qint64(0));
    }

    // Figures for the record (printed, not asserted: the machine decides them).
    void aDayReadAndReduced()
    {
        auto store = openOk(path("day.db"));
        QVERIFY(store);
        const qint64 id = *store->seriesId(makeSeries(QStringLiteral("1-R100")));
        const qint64 start = 1'800'000'000'000;
        std::vector<HistoryRecord> records;
        for (qint64 i = 0; i < 86'400; ++i)
            records.push_back({id, sample(start + i * 1000, std::sin(double(i) / 500.0) * 100,
                                          std::uint64_t(i))});
        QElapsedTimer timer;
        timer.start();
        QVERIFY(store->append(records));
        const qint64 appendMs = timer.elapsed();
        timer.start();
        const Result<std::vector<HistorySample>> day
            = store->samples(id, start, start + 86'400'000);
        const qint64 readNs = timer.nsecsElapsed();
        QVERIFY(day);
        QCOMPARE(day->size(), std::size_t(86'400));
        const std::vector<HistoryPoint> points = HistoryReducer::reduce(
            *day, start, start + 86'400'000, 1000, History::maxSilenceMs(600));
        const qint64 bothNs = timer.nsecsElapsed();
        QVERIFY(points.size() <= 4000);
        // One record per transaction: what a commit (its fsync, synchronous=FULL) costs.
        timer.start();
        for (qint64 i = 0; i < 20; ++i)
            QVERIFY(store->append({{id, sample(start - 1000 - i, 1)}}));
        const qint64 commitNs = timer.nsecsElapsed() / 20;
        qDebug("86,400 samples: append in one transaction %lld ms; read %.1f ms; read + reduce to "
               "%zu points %.1f ms; a one-sample commit %.2f ms",
               appendMs, double(readNs) / 1e6, points.size(), double(bothNs) / 1e6,
               double(commitNs) / 1e6);
    }

    void postgresUrlWithoutLibpq()
    {
        if (HistoryStore::hasPostgres())
            QSKIP("this build has libpq: PostgreSQL locations are tested with a server");
        Result<std::unique_ptr<HistoryStore>> store
            = HistoryStore::open(QStringLiteral("postgresql://fatek:secret@db.example/plant"),
                                 HistoryStore::Mode::ReadWrite);
        QVERIFY(!store);
        QVERIFY(idOf(store) == MessageId(MsgId::HistoryNoPostgres));
        const QString text = QString::fromStdString(english(store.error().message));
        QVERIFY2(text.contains(QLatin1String("postgresql://fatek@db.example/plant")),
                 qPrintable(text));
        QVERIFY(!text.contains(QLatin1String("secret")));
        QVERIFY(!HistoryStore::open(QStringLiteral("postgres://db/plant"),
                                    HistoryStore::Mode::ReadOnly));
        // Not a file of that name either.
        QVERIFY(!QFile::exists(QStringLiteral("postgres:")));
    }
};

QTEST_GUILESS_MAIN(TestHistoryStore)

#include "tst_historystore.moc"
