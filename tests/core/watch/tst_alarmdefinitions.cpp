// Alarm definitions in watch list files (issue 50): saved and loaded again as they were, files
// without alarms unchanged (still version 1), every unknown key and impossible definition refused
// with its table, item, alarm and line named.
#include "core/watch/watchlist.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace Fatek;

namespace {

template<typename T>
QString errorText(const Result<T> &r)
{
    return r.ok() ? QString() : QString::fromStdString(r.error().text());
}

WatchItemSpec entry(const char *address, DisplayFormat format, QList<AlarmDefinition> alarms)
{
    WatchItemSpec e;
    e.address = *Address::parse(address);
    e.format = format;
    e.alarms = std::move(alarms);
    return e;
}

AlarmDefinition alarm(AlarmKind kind, double limit = 0)
{
    AlarmDefinition a;
    a.kind = kind;
    a.limit = limit;
    return a;
}

QByteArray fileWithItem(const QByteArray &item)
{
    return R"({"format":"fatek-studio-watchlist","version":2,"tables":[{"name":"Main","items":[
  {"address":"R0"},
  )" + item + "\n]}]}";
}

} // namespace

class TestAlarmDefinitions : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTrip();
    void fileWithoutAlarmsStaysVersion1();
    void idsAndMessages();
    void loadErrors_data();
    void loadErrors();
    void validate_data();
    void validate();
};

void TestAlarmDefinitions::roundTrip()
{
    AlarmDefinition hh = alarm(AlarmKind::HighHigh, 95.5);
    hh.priority = AlarmPriority::Critical;
    hh.message = QStringLiteral("槽 1 溢流"); // non-ASCII survives
    hh.group = QStringLiteral("Tank farm");
    AlarmDefinition h = alarm(AlarmKind::High, 80);
    h.deadband = 2;
    h.onDelayMs = 1500;
    h.offDelayMs = 500;
    AlarmDefinition l = alarm(AlarmKind::Low, -10);
    l.enabled = false;
    AlarmDefinition q = alarm(AlarmKind::Quality);
    q.onDelayMs = 10000;
    WatchListFile file;
    WatchTableSpec table;
    table.name = QStringLiteral("Main");
    table.items = {entry("R100", DisplayFormat::Float32, {hh, h, l, q}),
                   entry("X3", DisplayFormat::Bit, {alarm(AlarmKind::On)}),
                   entry("R5", DisplayFormat::Signed, {})};
    file.tables = {table};
    const QByteArray saved = WatchList::save(file);
    QCOMPARE(QJsonDocument::fromJson(saved).object().value(QStringLiteral("version")).toInt(),
             WatchList::AlarmsVersion);
    const auto loaded = WatchList::load(saved);
    QVERIFY2(loaded.ok(), qPrintable(errorText(loaded)));
    QCOMPARE(*loaded, file);
}

void TestAlarmDefinitions::fileWithoutAlarmsStaysVersion1()
{
    const QByteArray old = R"({"format":"fatek-studio-watchlist","version":1,"tables":[
        {"name":"Main","items":[{"address":"R100","format":"signed"}]}]})";
    const auto loaded = WatchList::load(old);
    QVERIFY(loaded.ok());
    QVERIFY(loaded->tables.at(0).items.at(0).alarms.isEmpty());
    const QByteArray saved = WatchList::save(*loaded);
    QCOMPARE(QJsonDocument::fromJson(saved).object().value(QStringLiteral("version")).toInt(), 1);
    QVERIFY(!saved.contains("alarms"));
}

void TestAlarmDefinitions::idsAndMessages()
{
    WatchItemSpec e = entry("R100", DisplayFormat::Signed, {});
    e.station = 3;
    QCOMPARE(Alarms::alarmId(e, AlarmKind::HighHigh), QStringLiteral("3-R100-highHigh"));
    QCOMPARE(Alarms::defaultMessage(e, AlarmKind::LowLow), QStringLiteral("R100 low-low"));
    e.name = QStringLiteral("Tank level");
    QCOMPARE(Alarms::defaultMessage(e, AlarmKind::High), QStringLiteral("Tank level high"));
    AlarmDefinition a = alarm(AlarmKind::High, 1);
    QCOMPARE(Alarms::messageOf(e, a), QStringLiteral("Tank level high"));
    a.message = QStringLiteral("Overfill");
    QCOMPARE(Alarms::messageOf(e, a), QStringLiteral("Overfill"));
    for (AlarmKind k : Alarms::allKinds())
        QCOMPARE(Alarms::kindFromName(Alarms::kindName(k)), k);
}

void TestAlarmDefinitions::loadErrors_data()
{
    QTest::addColumn<QByteArray>("item");
    QTest::addColumn<QString>("message");
    const QString at = QStringLiteral("table 1, item 2: alarm 1: ");
    QTest::newRow("unknown key, with its line")
        << QByteArray(R"({"address":"R100","alarms":[{"type":"high","limit":80,
      "dedband":2}]})")
        << at
               + "line 4: unknown key \"dedband\" (known: type, limit, deadband, onDelayMs, "
                 "offDelayMs, priority, message, group, enabled); did you mean \"deadband\"?";
    QTest::newRow("unknown type") << QByteArray(R"({"address":"R100","alarms":[{"type":"hi"}]})")
                                  << at
                                         + "line 3: unknown type \"hi\" (known: highHigh, high, "
                                           "low, lowLow, on, off, quality)";
    QTest::newRow("no type") << QByteArray(R"({"address":"R100","alarms":[{"limit":1}]})")
                             << at
                                    + "the \"type\" is missing (one of: highHigh, high, low, "
                                      "lowLow, on, off, quality)";
    QTest::newRow("no limit") << QByteArray(R"({"address":"R100","alarms":[{"type":"low"}]})")
                              << at + "a low alarm needs a \"limit\"";
    QTest::newRow("limit on a bit alarm")
        << QByteArray(R"({"address":"X0","alarms":[{"type":"on","limit":1}]})")
        << at + "line 3: a on alarm has no \"limit\"";
    QTest::newRow("limit as text")
        << QByteArray(R"({"address":"R100","alarms":[{"type":"high","limit":"80"}]})")
        << at + "line 3: \"limit\" must be a number";
    QTest::newRow("negative delay")
        << QByteArray(R"({"address":"R100","alarms":[{"type":"high","limit":8,
      "onDelayMs":-1}]})")
        << at + "line 4: \"onDelayMs\" must be a whole number of milliseconds from 0 to 86400000";
    QTest::newRow("unknown priority")
        << QByteArray(
               R"({"address":"R100","alarms":[{"type":"high","limit":8,"priority":"urgent"}]})")
        << at + "line 3: unknown priority \"urgent\" (known: critical, high, medium, low)";
    QTest::newRow("enabled as text")
        << QByteArray(R"({"address":"R100","alarms":[{"type":"high","limit":8,"enabled":"no"}]})")
        << at + "line 3: \"enabled\" must be true or false";
    QTest::newRow("not a list") << QByteArray(R"({"address":"R100","alarms":{"type":"high"}})")
                                << "table 1, item 2: \"alarms\" must be a list";
    QTest::newRow("negative deadband")
        << QByteArray(R"({"address":"R100","alarms":[{"type":"high","limit":8,"deadband":-1}]})")
        << at + "the deadband -1 is negative";
    QTest::newRow("low above high")
        << QByteArray(R"({"address":"R100","alarms":[{"type":"high","limit":8},
      {"type":"low","limit":9}]})")
        << "table 1, item 2: the low limit 9 is above the high limit 8";
    QTest::newRow("second alarm's unknown key")
        << QByteArray(R"({"address":"R100","alarms":[{"type":"high","limit":8},
      {"type":"low","limit":1,
       "Limit":2}]})")
        << "table 1, item 2: alarm 2: line 5: unknown key \"Limit\" (known: type, limit, "
           "deadband, onDelayMs, offDelayMs, priority, message, group, enabled); did you mean "
           "\"limit\"?";
}

void TestAlarmDefinitions::loadErrors()
{
    QFETCH(QByteArray, item);
    QFETCH(QString, message);
    const auto r = WatchList::load(fileWithItem(item));
    QVERIFY(!r.ok());
    QCOMPARE(errorText(r), message);
}

void TestAlarmDefinitions::validate_data()
{
    QTest::addColumn<WatchItemSpec>("item");
    QTest::addColumn<QString>("message");
    AlarmDefinition negative = alarm(AlarmKind::High, 1);
    negative.deadband = -0.5;
    AlarmDefinition bitBand = alarm(AlarmKind::On);
    bitBand.deadband = 1;
    AlarmDefinition late = alarm(AlarmKind::High, 1);
    late.onDelayMs = -5;
    QTest::newRow("fine") << entry("R1", DisplayFormat::Signed,
                                   {alarm(AlarmKind::LowLow, -5), alarm(AlarmKind::Low, 0),
                                    alarm(AlarmKind::High, 10), alarm(AlarmKind::HighHigh, 10)})
                          << QString();
    QTest::newRow("two highs") << entry("R1", DisplayFormat::Signed,
                                        {alarm(AlarmKind::High, 1), alarm(AlarmKind::High, 2)})
                               << "alarm 2: a second high alarm (one of each type per item)";
    QTest::newRow("limit on a bit") << entry("Y0", DisplayFormat::Bit, {alarm(AlarmKind::High, 1)})
                                    << "alarm 1: a high alarm needs a number: this item is shown "
                                       "as bit";
    QTest::newRow("limit on ascii")
        << entry("R1", DisplayFormat::Ascii, {alarm(AlarmKind::Low, 1)})
        << "alarm 1: a low alarm needs a number: this item is shown as ascii";
    QTest::newRow("bit alarm on a register")
        << entry("R1", DisplayFormat::Signed, {alarm(AlarmKind::Off)})
        << "alarm 1: an off alarm is for a bit (X, Y, M, S, T, C)";
    QTest::newRow("negative deadband") << entry("R1", DisplayFormat::Signed, {negative})
                                       << "alarm 1: the deadband -0.5 is negative";
    QTest::newRow("deadband on a bit")
        << entry("X1", DisplayFormat::Bit, {bitBand}) << "alarm 1: a on alarm has no deadband";
    QTest::newRow("negative delay") << entry("R1", DisplayFormat::Signed, {late})
                                    << "alarm 1: the delays must be from 0 to 86400000 ms";
    QTest::newRow("high above high-high") << entry(
        "R1", DisplayFormat::Signed, {alarm(AlarmKind::High, 11), alarm(AlarmKind::HighHigh, 10)})
                                          << "the high limit 11 is above the high-high limit 10";
    QTest::newRow("low-low above low") << entry(
        "R1", DisplayFormat::Signed, {alarm(AlarmKind::Low, 1), alarm(AlarmKind::LowLow, 2)})
                                       << "the low-low limit 2 is above the low limit 1";
    QTest::newRow("low at high") << entry("R1", DisplayFormat::Unsigned,
                                          {alarm(AlarmKind::Low, 5), alarm(AlarmKind::High, 5)})
                                 << "the low limit 5 is above the high limit 5";
    QTest::newRow("low-low above high-high")
        << entry("R1", DisplayFormat::Float32,
                 {alarm(AlarmKind::LowLow, 50), alarm(AlarmKind::HighHigh, 10)})
        << "the low-low limit 50 is above the high-high limit 10";
}

void TestAlarmDefinitions::validate()
{
    QFETCH(WatchItemSpec, item);
    QFETCH(QString, message);
    const Status s = WatchList::validateEntry(item);
    QCOMPARE(s.ok() ? QString() : QString::fromStdString(s.error().text()), message);
}

QTEST_GUILESS_MAIN(TestAlarmDefinitions)
#include "tst_alarmdefinitions.moc"
