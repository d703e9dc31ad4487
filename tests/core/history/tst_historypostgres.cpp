// The PostgreSQL history store against a real PostgreSQL server (initdb on a free loopback port):
// what an SQLite store does (round trips, the sample before a range, replacing, retention, the
// databases it refuses), what only a server has (two gateways at once, a wrong password, a
// server killed and restarted), and how long the writer's and the trend's typical calls take.
#include "core/history/historymessages.h"
#include "core/history/postgreshistorystore.h"

#include "postgresserver.h"

#include <QElapsedTimer>
#include <QtTest>

#include <cmath>
#include <cstring>
#include <latch>
#include <limits>
#include <thread>

using namespace Fatek;
using TestUtil::PostgresServer;

namespace {

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
using Mode = HistoryStore::Mode;

template<typename T>
QByteArray why(const Result<T> &result)
{
    return result ? QByteArray("ok") : QByteArray::fromStdString(result.error().text());
}

std::unique_ptr<HistoryStore> openStore(const QString &url, Mode mode = Mode::ReadWrite)
{
    auto store = PostgresHistoryStore::open(url, mode);
    if (!store) {
        qWarning("open %s: %s", qPrintable(url), store.error().text().c_str());
        return nullptr;
    }
    return std::move(store).value();
}

HistorySeries makeSeries(const QString &source, const QString &item)
{
    HistorySeries s;
    s.source = source;
    s.item = item;
    s.label = QStringLiteral("Tank level");
    s.format = QStringLiteral("float");
    s.heartbeatS = 60;
    return s;
}

HistorySample sample(qint64 timeMs, double value, std::uint64_t raw = 0,
                     HistoryQuality quality = HistoryQuality::Good)
{
    return HistorySample{timeMs, value, raw, quality};
}

std::vector<HistoryRecord> records(qint64 series, const std::vector<HistorySample> &samples)
{
    std::vector<HistoryRecord> list;
    for (const HistorySample &s : samples)
        list.push_back(HistoryRecord{series, s});
    return list;
}

// Evenly spaced samples of one series, value = index.
std::vector<HistoryRecord> ramp(qint64 series, qint64 fromMs, qint64 stepMs, int count)
{
    std::vector<HistoryRecord> list;
    list.reserve(std::size_t(count));
    for (int i = 0; i < count; ++i)
        list.push_back(HistoryRecord{series, sample(fromMs + i * stepMs, i, std::uint64_t(i))});
    return list;
}

QList<qint64> times(const std::vector<HistorySample> &samples)
{
    QList<qint64> list;
    for (const HistorySample &s : samples)
        list.append(s.timeMs);
    return list;
}

} // namespace

class TestHistoryPostgres : public QObject
{
    Q_OBJECT

private:
    // A new database for one test, owned by the test role; its URL.
    QString database(const QString &name)
    {
        QString error;
        if (!m_server.createDatabase(name, &error))
            qWarning("%s", qPrintable(error));
        return m_server.url(name);
    }
    QString value(const QString &db, const QString &sql) const { return m_server.value(db, sql); }

    PostgresServer m_server;

private Q_SLOTS:
    void initTestCase()
    {
        QString error;
        QVERIFY2(m_server.start(&error), qPrintable(error));
    }

    void location()
    {
        const auto masked = &PostgresHistoryStore::withoutPassword;
        QCOMPARE(masked(QStringLiteral("postgresql://fatek:secret@db:5432/plant")),
                 QStringLiteral("postgresql://fatek@db:5432/plant"));
        QCOMPARE(masked(QStringLiteral("postgres://fatek:s:e@cret@h1,h2/plant?sslmode=require&"
                                       "password=x")),
                 QStringLiteral("postgres://fatek@h1,h2/plant?sslmode=require"));
        QCOMPARE(masked(QStringLiteral("postgresql:///plant?host=/run/pg&password=x")),
                 QStringLiteral("postgresql:///plant?host=/run/pg"));
        QCOMPARE(masked(QStringLiteral("host=db user=fatek password='a b' dbname=plant")),
                 QStringLiteral("host=db user=fatek dbname=plant"));
        QCOMPARE(masked(QStringLiteral("postgresql://db/plant")),
                 QStringLiteral("postgresql://db/plant"));

        const QString url = database(QStringLiteral("location"));
        auto store = openStore(url);
        QVERIFY(store);
        QCOMPARE(store->location(),
                 QStringLiteral("postgresql://fatek@127.0.0.1:%1/location").arg(m_server.port()));
        // The session says who it is (pg_stat_activity), for the database's administrator.
        QCOMPARE(value(QStringLiteral("location"),
                       QStringLiteral("SELECT count(*) FROM pg_stat_activity "
                                      "WHERE application_name = 'fatek-history'")),
                 QStringLiteral("1"));
    }

    void roundTrip()
    {
        auto store = openStore(database(QStringLiteral("roundtrip")));
        QVERIFY(store);
        HistorySeries tank = makeSeries(QStringLiteral("line1"), QStringLiteral("1-R100"));
        const Result<qint64> id = store->seriesId(tank);
        QVERIFY2(id, why(id));
        const Result<qint64> other
            = store->seriesId(makeSeries(QStringLiteral("line1"), QStringLiteral("1-D0")));
        QVERIFY2(other, why(other));
        QVERIFY(*id != *other);

        const std::vector<HistorySample> written{
            sample(1000, 1.5, 0x3FC00000),
            sample(2000, NaN, 0x8000000000000001ull, HistoryQuality::Stale),
            sample(3000, -0.0, 0x80000000, HistoryQuality::Late),
            sample(4000, 1e300, ~std::uint64_t{0}, HistoryQuality::Error),
            sample(5000, -std::numeric_limits<double>::infinity(), 0, HistoryQuality::Off),
            sample(6000, 4.9e-324, 1, HistoryQuality::Good),
        };
        QVERIFY2(store->append(records(*id, written)), "append");
        QVERIFY2(store->append(records(*other, {sample(2500, 7, 7)})), "append");
        const auto read = store->samples(*id, 0, 10000);
        QVERIFY2(read, why(read));
        QCOMPARE(read->size(), written.size());
        for (std::size_t i = 0; i < written.size(); ++i) {
            QVERIFY2((*read)[i] == written[i], qPrintable(QString::number(i)));
            // Bit for bit: -0.0 stays negative, the denormal stays.
            QCOMPARE(std::signbit((*read)[i].value), std::signbit(written[i].value));
        }
        QCOMPARE(store->sampleCount().value(), 7);
        QVERIFY(store->sizeBytes().value() > 0);

        // The same (source, item) is the same id; its description follows the watch list.
        tank.label = QStringLiteral("Tank 1 level");
        tank.heartbeatS = 30;
        QCOMPARE(store->seriesId(tank).value(), *id);
        const auto all = store->series();
        QVERIFY2(all, why(all));
        QCOMPARE(all->size(), 2);
        QCOMPARE(all->at(0).item, QStringLiteral("1-D0")); // by source, then item
        HistorySeries expected = tank;
        expected.id = *id;
        QCOMPARE(all->at(1), expected);
    }

    void sampleBeforeRange()
    {
        auto store = openStore(database(QStringLiteral("range")));
        QVERIFY(store);
        const qint64 id
            = store->seriesId(makeSeries(QStringLiteral("a"), QStringLiteral("1-R1"))).value();
        const qint64 other
            = store->seriesId(makeSeries(QStringLiteral("a"), QStringLiteral("1-R2"))).value();
        QVERIFY(store->append(ramp(id, 1000, 1000, 10))); // 1000 .. 10000
        QVERIFY(store->append(records(other, {sample(3400, 1), sample(3600, 2)})));
        QCOMPARE(times(store->samples(id, 3500, 6000).value()), (QList<qint64>{3000, 4000, 5000}));
        QCOMPARE(times(store->samples(id, 0, 2500).value()), (QList<qint64>{1000, 2000}));
        QCOMPARE(times(store->samples(id, 3000, 3001).value()), (QList<qint64>{2000, 3000}));
        QCOMPARE(times(store->samples(id, 20000, 30000).value()), (QList<qint64>{10000}));
        QCOMPARE(times(store->samples(id, 3500, 10001, 2).value()), (QList<qint64>{3000, 4000}));
        QCOMPARE(times(store->samples(id + other + 1, 0, 10000).value()), QList<qint64>{});
    }

    void replaceSameTime()
    {
        auto store = openStore(database(QStringLiteral("replace")));
        QVERIFY(store);
        const qint64 id
            = store->seriesId(makeSeries(QStringLiteral("a"), QStringLiteral("1-R1"))).value();
        QVERIFY(store->append(records(id, {sample(1000, 1, 1), sample(2000, 2, 2)})));
        QVERIFY(store->append(records(id, {sample(1000, NaN, 9, HistoryQuality::Stale)})));
        // Twice in one batch: the later one is kept, as two batches would.
        QVERIFY(store->append(
            records(id, {sample(2000, 5, 5), sample(2000, 6, 6, HistoryQuality::Late)})));
        const std::vector<HistorySample> expected{sample(1000, NaN, 9, HistoryQuality::Stale),
                                                  sample(2000, 6, 6, HistoryQuality::Late)};
        QVERIFY(store->samples(id, 0, 5000).value() == expected);
        QCOMPARE(store->sampleCount().value(), 2);
        // A sample of an unknown series is refused (the foreign key), in the store's words.
        const Status refused = store->append(records(id + 100, {sample(1000, 1)}));
        QVERIFY(!refused);
        QVERIFY(refused.error().message.id == MsgId::HistoryWriteFailed);
        QCOMPARE(store->sampleCount().value(), 2);
    }

    // Two gateways start at once on a new database: both make (or find) the tables, get the same
    // ids for the same series, write into one store; a studio reads both.
    void twoGateways()
    {
        const QString url = database(QStringLiteral("gateways"));
        constexpr int Series = 20;
        std::latch go(2);
        struct Gateway
        {
            QString source;
            std::string error;
            QList<qint64> shared;
            qint64 own = 0;
        } gateways[2];
        gateways[0].source = QStringLiteral("north");
        gateways[1].source = QStringLiteral("south");
        auto run = [&](Gateway &g) {
            go.arrive_and_wait();
            auto store = PostgresHistoryStore::open(url, Mode::ReadWrite);
            if (!store) {
                g.error = store.error().text();
                return;
            }
            for (int i = 0; i < Series; ++i) {
                auto id = (*store)->seriesId(
                    makeSeries(QStringLiteral("shared"), QStringLiteral("1-R%1").arg(i)));
                if (!id) {
                    g.error = id.error().text();
                    return;
                }
                g.shared.append(*id);
            }
            auto own = (*store)->seriesId(makeSeries(g.source, QStringLiteral("1-R0")));
            Status written
                = own ? (*store)->append(ramp(*own, 1000, 1000, 100)) : Status(own.error());
            if (written)
                written = (*store)->append(
                    ramp(g.shared.front(), g.source == u"north" ? 0 : 500, 1000, 100));
            if (!written)
                g.error = written.error().text();
            g.own = own ? *own : 0;
        };
        std::thread north(run, std::ref(gateways[0]));
        std::thread south(run, std::ref(gateways[1]));
        north.join();
        south.join();
        for (const Gateway &g : gateways)
            QVERIFY2(g.error.empty(), g.error.c_str());
        QCOMPARE(gateways[0].shared, gateways[1].shared);
        QVERIFY(gateways[0].own != gateways[1].own);

        auto studio = openStore(url, Mode::ReadOnly);
        QVERIFY(studio);
        const auto all = studio->series();
        QVERIFY2(all, why(all));
        QCOMPARE(all->size(), Series + 2);
        QCOMPARE(studio->samples(gateways[0].own, 0, 1'000'000).value().size(), 100u);
        QCOMPARE(studio->samples(gateways[1].own, 0, 1'000'000).value().size(), 100u);
        QCOMPARE(studio->samples(gateways[0].shared.front(), 0, 1'000'000).value().size(), 200u);
        QCOMPARE(studio->sampleCount().value(), 400);
    }

    void foreignTablesRefused()
    {
        const QString db = QStringLiteral("foreigntables");
        const QString url = database(db);
        QString error;
        QVERIFY2(m_server.exec(
                     db,
                     QStringLiteral(
                         "SET ROLE fatek; CREATE TABLE fatek_history_samples (id int, note text);"
                         "INSERT INTO fatek_history_samples VALUES (1, 'x')"),
                     &error),
                 qPrintable(error));
        for (const Mode mode : {Mode::ReadWrite, Mode::ReadOnly}) {
            const auto refused = PostgresHistoryStore::open(url, mode);
            QVERIFY(!refused);
            QVERIFY2(refused.error().message.id == MsgId::HistoryNotHistory, why(refused));
        }
        QCOMPARE(value(db, QStringLiteral("SELECT to_regclass('fatek_history_meta') IS NULL")),
                 QStringLiteral("t"));
        QCOMPARE(
            value(db, QStringLiteral("SELECT string_agg(note, ',') FROM fatek_history_samples")),
            QStringLiteral("x"));
        // Another program's meta table: with other columns, or another program's mark.
        QVERIFY2(m_server.exec(
                     db, QStringLiteral("SET ROLE fatek; CREATE TABLE fatek_history_meta (k int)"),
                     &error),
                 qPrintable(error));
        const auto otherColumns = PostgresHistoryStore::open(url, Mode::ReadWrite);
        QVERIFY(!otherColumns);
        QVERIFY2(otherColumns.error().message.id == MsgId::HistoryNotHistory, why(otherColumns));
        const QString db2 = QStringLiteral("foreignmeta");
        const QString url2 = database(db2);
        QVERIFY2(m_server.exec(
                     db2,
                     QStringLiteral(
                         "SET ROLE fatek; CREATE TABLE fatek_history_meta (key text, value text);"
                         "INSERT INTO fatek_history_meta VALUES "
                         "('format', '1'), ('application', 'other')"),
                     &error),
                 qPrintable(error));
        const auto otherMark = PostgresHistoryStore::open(url2, Mode::ReadWrite);
        QVERIFY(!otherMark);
        QVERIFY2(otherMark.error().message.id == MsgId::HistoryNotHistory, why(otherMark));
        QCOMPARE(value(db2, QStringLiteral("SELECT to_regclass('fatek_history_series') IS NULL")),
                 QStringLiteral("t"));
    }

    void newerFormatRefused()
    {
        const QString db = QStringLiteral("newer");
        const QString url = database(db);
        QVERIFY(openStore(url));
        QString error;
        QVERIFY2(m_server.exec(db,
                               QStringLiteral("UPDATE fatek_history_meta SET value = '2' "
                                              "WHERE key = 'format'"),
                               &error),
                 qPrintable(error));
        for (const Mode mode : {Mode::ReadWrite, Mode::ReadOnly}) {
            const auto refused = PostgresHistoryStore::open(url, mode);
            QVERIFY(!refused);
            const Message &m = refused.error().message;
            QVERIFY2(m.id == MsgId::HistoryNewer, why(refused));
            QCOMPARE(m.args.at(1).text, std::string("2"));
            QCOMPARE(m.args.at(2).text, std::to_string(HistoryStore::FormatVersion));
        }
        QCOMPARE(value(db, QStringLiteral("SELECT value FROM fatek_history_meta "
                                          "WHERE key = 'format'")),
                 QStringLiteral("2"));
    }

    void openRefused()
    {
        const QString db = QStringLiteral("login");
        database(db);
        // A wrong password: PostgreSQL's reason, and the location without the password tried.
        const auto wrong = PostgresHistoryStore::open(m_server.url(db, QStringLiteral("wrong-pw")),
                                                      Mode::ReadWrite);
        QVERIFY(!wrong);
        QVERIFY2(wrong.error().message.id == MsgId::HistoryOpenFailed, why(wrong));
        QVERIFY2(wrong.error().text().find("password authentication failed") != std::string::npos,
                 why(wrong));
        QVERIFY2(wrong.error().text().find("wrong-pw") == std::string::npos, why(wrong));
        QCOMPARE(wrong.error().kind, ErrorKind::LinkError);
        // A database that does not exist; a port nobody listens on.
        const auto missing
            = PostgresHistoryStore::open(m_server.url(QStringLiteral("nosuchdb")), Mode::ReadWrite);
        QVERIFY(!missing);
        QVERIFY2(missing.error().text().find("does not exist") != std::string::npos, why(missing));
        const auto refused = PostgresHistoryStore::open(
            QStringLiteral("postgresql://fatek@127.0.0.1:1/x"), Mode::ReadOnly);
        QVERIFY(!refused);
        QVERIFY2(refused.error().message.id == MsgId::HistoryOpenFailed, why(refused));
        // A reader of a database without a store: missing, and nothing was made.
        const auto empty = PostgresHistoryStore::open(m_server.url(db), Mode::ReadOnly);
        QVERIFY(!empty);
        QVERIFY2(empty.error().message.id == MsgId::HistoryMissing, why(empty));
        QCOMPARE(value(db, QStringLiteral("SELECT count(*) FROM pg_tables WHERE tablename LIKE "
                                          "'fatek%'")),
                 QStringLiteral("0"));
    }

    // The server killed (as by a power cut) and started again: the append meanwhile fails, the
    // next one after the restart succeeds on the same store object.
    void serverRestart()
    {
        auto store = openStore(database(QStringLiteral("restart")));
        QVERIFY(store);
        const qint64 id
            = store->seriesId(makeSeries(QStringLiteral("a"), QStringLiteral("1-R1"))).value();
        QVERIFY(store->append(records(id, {sample(1000, 1)})));
        m_server.kill();
        QVERIFY(!m_server.isRunning());
        const Status lost = store->append(records(id, {sample(2000, 2)}));
        QVERIFY(!lost);
        QVERIFY2(lost.error().message.id == MsgId::HistoryWriteFailed, why(lost));
        QCOMPARE(lost.error().kind, ErrorKind::LinkError);
        // Still down: the next call tries again, and says so again.
        QVERIFY(!store->samples(id, 0, 10000));
        QString error;
        QVERIFY2(m_server.start(&error), qPrintable(error));
        const Status back = store->append(records(id, {sample(3000, 3)}));
        QVERIFY2(back, why(back));
        QCOMPARE(times(store->samples(id, 0, 10000).value()), (QList<qint64>{1000, 3000}));
    }

    void retentionByAge()
    {
        auto store = openStore(database(QStringLiteral("age")));
        QVERIFY(store);
        const qint64 now = 1'800'000'000'000;
        constexpr qint64 Hour = 3'600'000;
        const qint64 a
            = store->seriesId(makeSeries(QStringLiteral("a"), QStringLiteral("1-R1"))).value();
        const qint64 b
            = store->seriesId(makeSeries(QStringLiteral("a"), QStringLiteral("1-R2"))).value();
        QVERIFY(store->append(ramp(a, now - 240 * Hour, Hour, 241))); // 10 days, hourly
        QVERIFY(store->append(ramp(b, now - 240 * Hour, Hour, 241)));
        const auto outcome = store->applyRetention(HistoryRetention{3 * 24 * 3600, 0}, now);
        QVERIFY2(outcome, why(outcome));
        QCOMPARE(outcome->samplesRemoved, 2 * 168);
        QVERIFY(outcome->bytesBefore > 0 && outcome->bytesAfter > 0);
        QCOMPARE(store->sampleCount().value(), 2 * 73);
        QCOMPARE(store->samples(a, 0, now + 1).value().front().timeMs, now - 72 * Hour);
        // Nothing older left: a second pass removes nothing.
        QCOMPARE(store->applyRetention(HistoryRetention{3 * 24 * 3600, 0}, now)->samplesRemoved, 0);
    }

    // PostgreSQL keeps the space of deleted rows for new ones: after a pass the tables keep their
    // size, the oldest samples are gone, and new samples fill the space instead of growing it.
    void retentionBySize()
    {
        auto store = openStore(database(QStringLiteral("size")));
        QVERIFY(store);
        constexpr int Series = 4;
        constexpr int PerSeries = 25'000;
        QList<qint64> ids;
        for (int i = 0; i < Series; ++i)
            ids.append(
                store->seriesId(makeSeries(QStringLiteral("a"), QStringLiteral("1-R%1").arg(i)))
                    .value());
        auto fill = [&](qint64 fromMs) -> Status {
            for (int t = 0; t < PerSeries; t += 5000) {
                std::vector<HistoryRecord> batch;
                for (int step = t; step < t + 5000; ++step) {
                    for (const qint64 id : ids)
                        batch.push_back(HistoryRecord{id, sample(fromMs + step * 1000, step, 1)});
                }
                if (Status s = store->append(batch); !s)
                    return s;
            }
            return Ok{};
        };
        QVERIFY(fill(0));
        const qint64 full = store->sizeBytes().value();
        const qint64 now = PerSeries * 1000;
        // Room enough: nothing goes.
        QCOMPARE(store->applyRetention(HistoryRetention{0, full * 2}, now)->samplesRemoved, 0);

        const auto half = store->applyRetention(HistoryRetention{0, full / 2}, now);
        QVERIFY2(half, why(half));
        const qint64 left = store->sampleCount().value();
        qDebug("size %lld bytes, %d samples; limit %lld: %lld removed, %lld bytes after", full,
               Series * PerSeries, full / 2, half->samplesRemoved, half->bytesAfter);
        QCOMPARE(left + half->samplesRemoved, qint64(Series * PerSeries));
        QVERIFY2(left > Series * PerSeries * 3 / 10 && left < Series * PerSeries * 6 / 10,
                 qPrintable(QString::number(left)));
        // The oldest went, in every series; the newest stayed.
        for (const qint64 id : ids) {
            const auto kept = store->samples(id, 0, now).value();
            QVERIFY(kept.front().timeMs > 0);
            QCOMPARE(kept.back().timeMs, now - 1000);
        }
        // The writer's rhythm: a pass after each batch of new samples (as many in all as went).
        // The space of the deleted rows is reused: the tables grow little.
        for (int batch = 0; batch < 10; ++batch) {
            std::vector<HistoryRecord> more;
            for (int step = 0; step < 1250; ++step) {
                const qint64 t = now + (batch * 1250 + step) * 1000;
                for (const qint64 id : ids)
                    more.push_back(HistoryRecord{id, sample(t, step, 1)});
            }
            QVERIFY(store->append(more));
            QVERIFY(store->applyRetention(HistoryRetention{0, full / 2}, now));
        }
        const qint64 after = store->sizeBytes().value();
        qDebug("after 50,000 more, a pass after each 5,000: %lld bytes, %lld samples", after,
               store->sampleCount().value());
        QVERIFY2(after < full * 12 / 10, qPrintable(QString::number(after)));
        QVERIFY(store->sampleCount().value() < Series * PerSeries * 6 / 10);
    }

    void readOnlyChangesNothing()
    {
        const QString url = database(QStringLiteral("readonly"));
        auto writer = openStore(url);
        QVERIFY(writer);
        const HistorySeries s = makeSeries(QStringLiteral("a"), QStringLiteral("1-R1"));
        const qint64 id = writer->seriesId(s).value();
        QVERIFY(writer->append(ramp(id, 1000, 1000, 10)));
        auto reader = openStore(url, Mode::ReadOnly);
        QVERIFY(reader);
        QCOMPARE(reader->samples(id, 0, 100000).value().size(), 10u);
        QCOMPARE(reader->sampleCount().value(), 10);
        HistorySeries renamed = s;
        renamed.label = QStringLiteral("renamed");
        const auto refusedSeries = reader->seriesId(renamed);
        QVERIFY(!refusedSeries);
        QCOMPARE(refusedSeries.error().kind, ErrorKind::ReadOnly);
        const Status refusedAppend = reader->append(ramp(id, 20000, 1000, 10));
        QVERIFY(!refusedAppend);
        QVERIFY2(refusedAppend.error().message.id == MsgId::HistoryWriteFailed, why(refusedAppend));
        QVERIFY(!reader->applyRetention(HistoryRetention{1, 0}, 1'000'000'000));
        QCOMPARE(writer->sampleCount().value(), 10);
        QCOMPARE(writer->series()->front().label, s.label);
    }

    // Figures, not limits: the writer's second of a large plant, a day of one series for a trend.
    void timings()
    {
        auto store = openStore(database(QStringLiteral("timings")));
        QVERIFY(store);
        QList<qint64> ids;
        for (int i = 0; i < 100; ++i)
            ids.append(
                store->seriesId(makeSeries(QStringLiteral("a"), QStringLiteral("1-R%1").arg(i)))
                    .value());
        std::vector<HistoryRecord> second;
        for (int t = 0; t < 100; ++t) {
            for (const qint64 id : ids)
                second.push_back(HistoryRecord{id, sample(t * 10, t * 0.25, std::uint64_t(t))});
        }
        QElapsedTimer timer;
        timer.start();
        QVERIFY(store->append(second));
        qDebug("append of 10,000 records (100 series) in one transaction: %lld ms",
               timer.elapsed());
        timer.restart();
        QVERIFY(store->append(second)); // all replaced
        qDebug("the same 10,000 again (each replaces a stored sample): %lld ms", timer.elapsed());

        const qint64 day
            = store->seriesId(makeSeries(QStringLiteral("b"), QStringLiteral("1-R0"))).value();
        timer.restart();
        QVERIFY(store->append(ramp(day, 0, 1000, 86'400)));
        qDebug("append of 86,400 records of one series: %lld ms", timer.elapsed());
        timer.restart();
        const auto read = store->samples(day, 0, 86'400'000);
        const qint64 ms = timer.elapsed();
        QVERIFY2(read, why(read));
        QCOMPARE(read->size(), 86'400u);
        qDebug("read of 86,400 samples of one series: %lld ms", ms);
    }
};

QTEST_GUILESS_MAIN(TestHistoryPostgres)
#include "tst_historypostgres.moc"
