// fatek-cli history (issue 51), the real program reading a store written through the history's
// own API: the series listed, samples of a range as text, CSV and JSON lines (the time local with
// its offset, the raw words, the quality; a gap without a value), an item named by its address or
// label, and the refusals with their exit codes (a store that does not exist, an item that names
// no series or several, a range that ends before it begins, a file that is not a store).

#include "core/history/historystore.h"

#include <QDateTime>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace Fatek;

namespace {

struct Run
{
    int code = -1;
    QByteArray out, err;
};

Run runCli(const QStringList &arguments)
{
    QProcess process;
    process.start(QStringLiteral(FATEK_CLI_PATH),
                  QStringList{QStringLiteral("history")} + arguments);
    Run run;
    if (!process.waitForFinished(30000)) {
        process.kill();
        process.waitForFinished();
        return run;
    }
    run.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

// 2026-12-07 08:00:00 UTC.
constexpr qint64 T0 = 1796630400000;

} // namespace

class TestCliHistory : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_store;

private Q_SLOTS:
    void initTestCase();
    void listsSeries();
    void samplesAsText();
    void samplesAsCsv();
    void samplesAsJson();
    void refusals();
};

void TestCliHistory::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_store = m_dir.filePath(QStringLiteral("history.sqlite"));
    Result<std::unique_ptr<HistoryStore>> store
        = HistoryStore::open(m_store, HistoryStore::Mode::ReadWrite);
    QVERIFY2(store, store ? "" : store.error().text().c_str());
    HistorySeries level{0,
                        QStringLiteral("line1"),
                        QStringLiteral("1-R100"),
                        QStringLiteral("Tank level"),
                        QStringLiteral("signed"),
                        600};
    HistorySeries temp{0,         QStringLiteral("line1"), QStringLiteral("1-R200"),
                       QString(), QStringLiteral("float"), 60};
    // The same address on another line: "R100" alone names two series.
    HistorySeries other{0,         QStringLiteral("line2"),  QStringLiteral("1-R100"),
                        QString(), QStringLiteral("signed"), 600};
    const Result<qint64> a = (*store)->seriesId(level);
    const Result<qint64> b = (*store)->seriesId(temp);
    const Result<qint64> c = (*store)->seriesId(other);
    QVERIFY(a && b && c);
    std::vector<HistoryRecord> records;
    // R100: one value a minute for an hour, a gap (stale) at minute 30.
    for (int m = 0; m < 60; ++m) {
        HistorySample s;
        s.timeMs = T0 + m * 60000LL;
        s.quality = m == 30 ? HistoryQuality::Stale : HistoryQuality::Good;
        s.value = m == 30 ? std::nan("") : 100 + m;
        s.raw = static_cast<std::uint64_t>(100 + m);
        records.push_back({*a, s});
    }
    HistorySample f;
    f.timeMs = T0;
    f.value = static_cast<double>(0.1f);
    f.raw = 0x3dcccccd;
    records.push_back({*b, f});
    HistorySample o;
    o.timeMs = T0;
    o.value = 5;
    o.raw = 5;
    records.push_back({*c, o});
    QVERIFY((*store)->append(records));
}

void TestCliHistory::listsSeries()
{
    const Run run = runCli({m_store});
    QCOMPARE(run.code, 0);
    const QStringList lines = QString::fromUtf8(run.out).split(u'\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 3);
    QCOMPARE(lines.at(0), QStringLiteral("line1/1-R100  Tank level  signed  heartbeat 600 s"));
    QVERIFY2(lines.at(1).startsWith(QLatin1String("line1/1-R200  -  float")),
             qPrintable(lines.at(1)));
    QVERIFY(lines.at(2).startsWith(QLatin1String("line2/1-R100")));
}

void TestCliHistory::samplesAsText()
{
    // 08:10 to 08:40 UTC: minutes 10..39, the stale one printed without a value.
    const Run run = runCli({m_store, QStringLiteral("Tank level"), QStringLiteral("--from"),
                            QStringLiteral("2026-12-07T08:10:00Z"), QStringLiteral("--to"),
                            QStringLiteral("2026-12-07T08:40:00Z")});
    QCOMPARE(run.code, 0);
    const QStringList lines = QString::fromUtf8(run.out).split(u'\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 30);
    const QString first = QDateTime::fromMSecsSinceEpoch(T0 + 10 * 60000LL)
                              .toOffsetFromUtc(QDateTime::fromMSecsSinceEpoch(T0).offsetFromUtc())
                              .toString(Qt::ISODateWithMs);
    QCOMPARE(lines.first(), first + QStringLiteral("  line1/1-R100  110  good"));
    QVERIFY2(lines.at(20).endsWith(QLatin1String("line1/1-R100  -  stale")),
             qPrintable(lines.at(20)));
    QVERIFY(lines.last().endsWith(QLatin1String("  139  good")));
    // --limit stops early.
    const Run limited = runCli({m_store, QStringLiteral("line1/1-R100"), QStringLiteral("--from"),
                                QStringLiteral("2026-12-07T08:00:00Z"), QStringLiteral("--to"),
                                QStringLiteral("2026-12-07T09:00:00Z"), QStringLiteral("--limit"),
                                QStringLiteral("5")});
    QCOMPARE(limited.code, 0);
    QCOMPARE(QString::fromUtf8(limited.out).count(u'\n'), 5);
}

void TestCliHistory::samplesAsCsv()
{
    const Run run = runCli({m_store, QStringLiteral("R200"), QStringLiteral("line1/1-R100"),
                            QStringLiteral("--from=2026-12-07T08:00:00Z"),
                            QStringLiteral("--to=2026-12-07T08:02:00Z"), QStringLiteral("--csv")});
    QCOMPARE(run.code, 0);
    const QStringList lines = QString::fromUtf8(run.out).split(u'\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 4);
    QCOMPARE(lines.at(0), QStringLiteral("time,series,value,raw,quality"));
    // A float item's value as the float it is, not as its double.
    QVERIFY2(lines.at(1).endsWith(QLatin1String(",line1/1-R200,0.1,0x000000003dcccccd,good")),
             qPrintable(lines.at(1)));
    QVERIFY(lines.at(2).endsWith(QLatin1String(",line1/1-R100,100,0x0000000000000064,good")));
    QVERIFY(lines.at(3).endsWith(QLatin1String(",line1/1-R100,101,0x0000000000000065,good")));
}

void TestCliHistory::samplesAsJson()
{
    const Run run = runCli({m_store, QStringLiteral("1-R100"), QStringLiteral("--from"),
                            QStringLiteral("2026-12-07T08:29:00Z"), QStringLiteral("--to"),
                            QStringLiteral("2026-12-07T08:31:00Z"), QStringLiteral("--json")});
    // "1-R100" is on two lines: refused, naming both.
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains("line1/1-R100, line2/1-R100"), run.err.constData());
    const Run one = runCli({m_store, QStringLiteral("line1/1-R100"), QStringLiteral("--from"),
                            QStringLiteral("2026-12-07T08:29:00Z"), QStringLiteral("--to"),
                            QStringLiteral("2026-12-07T08:31:00Z"), QStringLiteral("--json")});
    QCOMPARE(one.code, 0);
    const QList<QByteArray> lines = one.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 2);
    const QJsonObject good = QJsonDocument::fromJson(lines.at(0)).object();
    QCOMPARE(good.value(QStringLiteral("timeMs")).toInteger(), T0 + 29 * 60000LL);
    QCOMPARE(good.value(QStringLiteral("value")).toDouble(), 129.0);
    QCOMPARE(good.value(QStringLiteral("quality")).toString(), QStringLiteral("good"));
    QCOMPARE(good.value(QStringLiteral("series")).toString(), QStringLiteral("line1/1-R100"));
    const QJsonObject stale = QJsonDocument::fromJson(lines.at(1)).object();
    QVERIFY(stale.value(QStringLiteral("value")).isNull());
    QCOMPARE(stale.value(QStringLiteral("quality")).toString(), QStringLiteral("stale"));
}

void TestCliHistory::refusals()
{
    const Run missing = runCli({m_dir.filePath(QStringLiteral("none.sqlite"))});
    QCOMPARE(missing.code, 2);
    QVERIFY2(missing.err.contains("does not exist"), missing.err.constData());
    const Run unknown = runCli({m_store, QStringLiteral("R999")});
    QCOMPARE(unknown.code, 2);
    QVERIFY2(unknown.err.contains("R999 is no series of the store"), unknown.err.constData());
    const Run backwards
        = runCli({m_store, QStringLiteral("line1/1-R100"), QStringLiteral("--from"),
                  QStringLiteral("now"), QStringLiteral("--to"), QStringLiteral("-1h")});
    QCOMPARE(backwards.code, 2);
    QVERIFY2(backwards.err.contains("must come after --from"), backwards.err.constData());
    const Run badTime = runCli({m_store, QStringLiteral("line1/1-R100"), QStringLiteral("--from"),
                                QStringLiteral("yesterday")});
    QCOMPARE(badTime.code, 2);
    // A file that is not a store is refused, and left as it was.
    QFile foreign(m_dir.filePath(QStringLiteral("notes.txt")));
    QVERIFY(foreign.open(QIODevice::WriteOnly));
    foreign.write("not a database at all, just a few words of text\n");
    foreign.close();
    const Run notStore = runCli({foreign.fileName()});
    QCOMPARE(notStore.code, 1);
    QVERIFY(foreign.open(QIODevice::ReadOnly));
    QCOMPARE(foreign.readAll(), QByteArray("not a database at all, just a few words of text\n"));
}

QTEST_GUILESS_MAIN(TestCliHistory)
#include "tst_cli_history.moc"
