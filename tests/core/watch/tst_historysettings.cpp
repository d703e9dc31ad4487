// History settings in watch list files (issue 51): saved and loaded again as they were, files
// without them unchanged (still version 1), every unknown key and impossible setting refused with
// its table, item and line named.
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

WatchItemSpec entry(const char *address, DisplayFormat format,
                    std::optional<HistorySetting> history)
{
    WatchItemSpec e;
    e.address = *Address::parse(address);
    e.format = format;
    e.history = history;
    return e;
}

HistorySetting setting(double deadband, int heartbeatS = 600)
{
    HistorySetting h;
    h.deadband = deadband;
    h.heartbeatS = heartbeatS;
    return h;
}

QByteArray fileWithItem(const QByteArray &item)
{
    return R"({"format":"fatek-studio-watchlist","version":2,"tables":[{"name":"Main","items":[
  {"address":"R0"},
  )" + item + "\n]}]}";
}

int versionOf(const QByteArray &json)
{
    return QJsonDocument::fromJson(json).object().value(QStringLiteral("version")).toInt();
}

} // namespace

class TestHistorySettings : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTrip();
    void emptyObjectTakesTheDefaults();
    void fileWithoutHistoryStaysAsItWas();
    void historyAloneIsVersion2();
    void loadErrors_data();
    void loadErrors();
    void validate_data();
    void validate();
    void itemIdNamesStationAndAddress();
};

void TestHistorySettings::roundTrip()
{
    WatchListFile file;
    WatchTableSpec table;
    table.name = QStringLiteral("Main");
    table.items = {entry("R100", DisplayFormat::Float32, setting(0.25, 60)),
                   entry("X3", DisplayFormat::Bit, setting(0, HistorySetting::MaxHeartbeatS)),
                   entry("R10", DisplayFormat::Ascii, setting(0, HistorySetting::MinHeartbeatS)),
                   entry("R5", DisplayFormat::Signed, std::nullopt)};
    file.tables = {table};
    const QByteArray saved = WatchList::save(file);
    QCOMPARE(versionOf(saved), WatchList::ItemSettingsVersion);
    const auto loaded = WatchList::load(saved);
    QVERIFY2(loaded.ok(), qPrintable(errorText(loaded)));
    QCOMPARE(*loaded, file);
    QVERIFY(!loaded->tables.at(0).items.at(3).history);
    // Written only where there is one.
    QCOMPARE(saved.count("\"history\""), 3);
}

void TestHistorySettings::emptyObjectTakesTheDefaults()
{
    const auto loaded = WatchList::load(fileWithItem(R"({"address":"R100","history":{}})"));
    QVERIFY2(loaded.ok(), qPrintable(errorText(loaded)));
    QCOMPARE(loaded->tables.at(0).items.at(1).history, HistorySetting{});
    QVERIFY(!loaded->tables.at(0).items.at(0).history);
}

void TestHistorySettings::fileWithoutHistoryStaysAsItWas()
{
    WatchListFile file;
    WatchTableSpec table;
    table.name = QStringLiteral("Main");
    table.items = {entry("R100", DisplayFormat::Signed, std::nullopt)};
    file.tables = {table};
    const QByteArray saved = WatchList::save(file);
    QCOMPARE(versionOf(saved), 1);
    QVERIFY(!saved.contains("history"));
    // Loaded and saved again: byte for byte.
    const auto loaded = WatchList::load(saved);
    QVERIFY(loaded.ok());
    QCOMPARE(WatchList::save(*loaded), saved);
}

void TestHistorySettings::historyAloneIsVersion2()
{
    const QByteArray old = R"({"format":"fatek-studio-watchlist","version":1,"tables":[
        {"name":"Main","items":[{"address":"R100","format":"signed"}]}]})";
    const auto loaded = WatchList::load(old);
    QVERIFY(loaded.ok());
    WatchListFile file = *loaded;
    file.tables[0].items[0].history = setting(2);
    const QByteArray saved = WatchList::save(file);
    QCOMPARE(versionOf(saved), 2);
    QVERIFY(!saved.contains("alarms"));
    const auto again = WatchList::load(saved);
    QVERIFY(again.ok());
    QCOMPARE(again->tables.at(0).items.at(0).history, setting(2));
}

void TestHistorySettings::loadErrors_data()
{
    QTest::addColumn<QByteArray>("item");
    QTest::addColumn<QString>("message");
    const QString at = QStringLiteral("table 1, item 2: history: ");
    QTest::newRow("unknown key, with its line")
        << QByteArray(R"({"address":"R100","history":{"heartbeatS":60,
      "dedband":2}})")
        << at
               + "line 4: unknown key \"dedband\" (known: deadband, heartbeatS); did you mean "
                 "\"deadband\"?";
    QTest::newRow("key twice") << QByteArray(R"({"address":"R100","history":{"deadband":1,
      "deadband":2}})") << "line 4: duplicate key \"deadband\"";
    QTest::newRow("not an object") << QByteArray(R"({"address":"R100","history":true})")
                                   << "table 1, item 2: \"history\" must be a JSON object";
    QTest::newRow("null") << QByteArray(R"({"address":"R100","history":null})")
                          << "table 1, item 2: \"history\" must be a JSON object";
    QTest::newRow("deadband as text")
        << QByteArray(R"({"address":"R100","history":{"deadband":"1"}})")
        << at + "line 3: \"deadband\" must be a number";
    QTest::newRow("negative deadband")
        << QByteArray(R"({"address":"R100","history":{"deadband":-0.5}})")
        << at + "line 3: the deadband -0.5 is negative";
    QTest::newRow("deadband on a bit")
        << QByteArray(R"({"address":"Y0","history":{"deadband":1}})")
        << at + "an item shown as bit has no deadband (every change is kept)";
    QTest::newRow("deadband on ascii")
        << QByteArray(R"({"address":"R100","format":"ascii","history":{"deadband":1}})")
        << at + "an item shown as ascii has no deadband (every change is kept)";
    const QString heartbeat
        = at + "line 3: \"heartbeatS\" must be a whole number of seconds from 1 to 86400";
    QTest::newRow("heartbeat 0") << QByteArray(R"({"address":"R100","history":{"heartbeatS":0}})")
                                 << heartbeat;
    QTest::newRow("heartbeat above a day")
        << QByteArray(R"({"address":"R100","history":{"heartbeatS":86401}})") << heartbeat;
    QTest::newRow("heartbeat not whole")
        << QByteArray(R"({"address":"R100","history":{"heartbeatS":1.5}})") << heartbeat;
    QTest::newRow("heartbeat as text")
        << QByteArray(R"({"address":"R100","history":{"heartbeatS":"60"}})") << heartbeat;
}

void TestHistorySettings::loadErrors()
{
    QFETCH(QByteArray, item);
    QFETCH(QString, message);
    const auto r = WatchList::load(fileWithItem(item));
    QVERIFY(!r.ok());
    QCOMPARE(errorText(r), message);
}

void TestHistorySettings::validate_data()
{
    QTest::addColumn<WatchItemSpec>("item");
    QTest::addColumn<QString>("message");
    QTest::newRow("none") << entry("R1", DisplayFormat::Signed, std::nullopt) << QString();
    QTest::newRow("fine") << entry("DR1", DisplayFormat::Float32, setting(0.1, 1)) << QString();
    QTest::newRow("bit without deadband")
        << entry("M1", DisplayFormat::Bit, setting(0, 86400)) << QString();
    QTest::newRow("negative deadband") << entry("R1", DisplayFormat::Signed, setting(-1))
                                       << "history: the deadband -1 is negative";
    QTest::newRow("infinite deadband")
        << entry("R1", DisplayFormat::Signed, setting(std::numeric_limits<double>::infinity()))
        << "history: the deadband must be a number";
    QTest::newRow("NaN deadband") << entry("R1", DisplayFormat::Signed,
                                           setting(std::numeric_limits<double>::quiet_NaN()))
                                  << "history: the deadband must be a number";
    QTest::newRow("deadband on a bit") << entry("X1", DisplayFormat::Bit, setting(0.5))
                                       << "history: an item shown as bit has no deadband (every "
                                          "change is kept)";
    QTest::newRow("deadband on ascii") << entry("R1", DisplayFormat::Ascii, setting(0.5))
                                       << "history: an item shown as ascii has no deadband "
                                          "(every change is kept)";
    const QString heartbeat = QStringLiteral(
        "history: the heartbeat must be a whole number of seconds from 1 to 86400");
    QTest::newRow("heartbeat 0") << entry("R1", DisplayFormat::Signed, setting(0, 0)) << heartbeat;
    QTest::newRow("heartbeat above a day")
        << entry("R1", DisplayFormat::Signed, setting(0, 86401)) << heartbeat;
}

void TestHistorySettings::validate()
{
    QFETCH(WatchItemSpec, item);
    QFETCH(QString, message);
    const Status s = WatchList::validateEntry(item);
    QCOMPARE(s.ok() ? QString() : QString::fromStdString(s.error().text()), message);
    // Nothing half-checked is saved either.
    WatchListFile file;
    file.tables = {WatchTableSpec{QStringLiteral("T"), 500, true, {item}}};
    QCOMPARE(WatchList::validate(file).ok(), message.isEmpty());
}

void TestHistorySettings::itemIdNamesStationAndAddress()
{
    WatchItemSpec e = entry("R100", DisplayFormat::Signed, std::nullopt);
    QCOMPARE(WatchList::itemId(e), QStringLiteral("1-R100"));
    e.station = 12;
    e.address = *Address::parse("DWM16");
    QCOMPARE(WatchList::itemId(e), QStringLiteral("12-DWM16"));
    // Alarm ids are the item's id and the kind.
    QCOMPARE(Alarms::alarmId(e, AlarmKind::Low), QStringLiteral("12-DWM16-low"));
}

QTEST_GUILESS_MAIN(TestHistorySettings)
#include "tst_historysettings.moc"
