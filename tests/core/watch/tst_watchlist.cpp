#include "core/watch/jsonkeys.h"
#include "core/watch/watchlist.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;

namespace {

Address addr(const char *text)
{
    return *Address::parse(text);
}

template<typename T>
QString errorText(const Result<T> &r)
{
    return r.ok() ? QString() : QString::fromStdString(r.error().text());
}

WatchItemSpec entry(const char *address, DisplayFormat format, quint8 station = 1,
                    const QString &name = {}, const QString &comment = {}, bool swap = false)
{
    WatchItemSpec e;
    e.address = addr(address);
    e.format = format;
    e.station = station;
    e.name = name;
    e.comment = comment;
    e.swapWords = swap;
    return e;
}

WatchListFile sampleFile()
{
    WatchTableSpec main;
    main.name = QStringLiteral("Main");
    main.intervalMs = 500;
    main.confirmWrites = true;
    main.items = {
        entry("R100", DisplayFormat::Signed, 1, QStringLiteral("Tank level"),
              QStringLiteral("cm, from sensor \"A\"")),
        entry("X0", DisplayFormat::Bit, 1, QStringLiteral("Start button")),
        entry("DR10", DisplayFormat::Float32, 2, QString::fromUtf8("F\xC3\xBCllstand"), {}, true),
        entry("R200", DisplayFormat::Double64, 254),
        entry("WY0", DisplayFormat::Binary, 3),
        entry("D5", DisplayFormat::Bcd),
        entry("R300", DisplayFormat::Ascii),
        entry("DWM0", DisplayFormat::Hex),
        entry("RT5", DisplayFormat::Unsigned),
    };
    WatchTableSpec slow;
    slow.name = QStringLiteral("Slow");
    slow.intervalMs = 60000;
    slow.confirmWrites = false;
    WatchTableSpec empty;
    empty.name = QString();
    empty.intervalMs = 10;
    WatchListFile file;
    file.tables = {main, slow, empty};
    return file;
}

QByteArray fileWithItems(const QByteArray &items, const QByteArray &tableExtra = {})
{
    return R"({"format":"fatek-studio-watchlist","version":1,"tables":[{"name":"T")" + tableExtra
           + R"(,"items":[)" + items + "]}]}";
}

} // namespace

class TestWatchList : public QObject
{
    Q_OBJECT

private slots:
    void saveLoadRoundTrip();
    void savedJsonShape();
    void allowNonFiniteRoundTrip();
    void duplicateKeysOnlyWithinOneObject();
    void loadDefaults();
    void loadErrors_data();
    void loadErrors();
    void unknownKeysRefused_data();
    void unknownKeysRefused();
    void notJsonNamesLine();
    void errorNamesTableAndItem();
    void saveToFileAndBack();
    void saveToFileRefusesInvalid();
    void saveToFileUnwritable();
    void loadFromFileErrors();
    void validateEntry();

    void csvPositional();
    void csvHeader();
    void csvSemicolonsAndQuotes();
    void csvRanges();
    void csvSkipsBlankAndComments();
    void csvEncoding();
    void csvErrors_data();
    void csvErrors();

    void expandRange_data();
    void expandRange();
    void expandRangeErrors_data();
    void expandRangeErrors();
};

void TestWatchList::saveLoadRoundTrip()
{
    const WatchListFile file = sampleFile();
    const auto loaded = WatchList::load(WatchList::save(file));
    QVERIFY2(loaded.ok(), qPrintable(errorText(loaded)));
    QCOMPARE(loaded->tables.size(), 3);
    QCOMPARE(loaded->tables.at(0).items.size(), 9);
    QVERIFY(*loaded == file);
    // Saving what was loaded gives the same bytes: nothing drifts over load/save cycles.
    QCOMPARE(WatchList::save(*loaded), WatchList::save(file));
}

// Issue 48: the item option that lets writes put NaN or an infinity into a float, kept in the
// file only where it is on (every other file stays as it was).
void TestWatchList::allowNonFiniteRoundTrip()
{
    const auto loaded = WatchList::load(fileWithItems(
        R"({"address":"R10","format":"float","allowNonFinite":true},{"address":"R20"})"));
    QVERIFY2(loaded.ok(), qPrintable(errorText(loaded)));
    QVERIFY(loaded->tables.at(0).items.at(0).allowNonFinite);
    QVERIFY(!loaded->tables.at(0).items.at(1).allowNonFinite);
    const QByteArray saved = WatchList::save(*loaded);
    QCOMPARE(saved.count("allowNonFinite"), 1);
    QVERIFY(*WatchList::load(saved) == *loaded);
    QVERIFY(!WatchList::save(sampleFile()).contains("allowNonFinite"));
    // Duplicate values in different objects are no duplicate keys.
    QVERIFY(
        WatchList::load(fileWithItems(R"({"address":"R1","name":"x"},{"address":"R2","name":"x"})"))
            .ok());
}

// JsonKeys (issue 48) looks at keys only, each object's apart: strings that look like keys, the
// same key in nested or sibling objects, and values in lists are none.
void TestWatchList::duplicateKeysOnlyWithinOneObject()
{
    QVERIFY(
        !JsonKeys::firstDuplicate(R"({"a":"{\"a\":1,\"a\":2}","b":{"a":1,"b":[{"a":1},{"a":2}]},)"
                                  R"("c":["a","a"],"d":"x\\"})"));
    const std::optional<Message> twice
        = JsonKeys::firstDuplicate("{\"a\":{\"b\":1},\n\"c\":[{\"d\":\"}\"},\n{\"d\":1,\"d\":2}]}");
    QVERIFY(twice);
    QCOMPARE(QString::fromStdString(english(*twice)),
             QStringLiteral("line 3: duplicate key \"d\""));
}

void TestWatchList::savedJsonShape()
{
    const QByteArray json = WatchList::save(sampleFile());
    QVERIFY(json.contains("\"format\": \"fatek-studio-watchlist\""));
    QVERIFY(json.contains("\"version\": 1"));
    QVERIFY(json.contains("\"address\": \"DR10\""));
    QVERIFY(json.contains("\"format\": \"float\""));
    QVERIFY(json.contains("\"swapWords\": true"));
    QVERIFY(json.contains("\"intervalMs\": 60000"));
    QVERIFY(json.contains("\"confirmWrites\": false"));
    QVERIFY(json.contains('\n')); // pretty, so it diffs well under version control
}

void TestWatchList::loadDefaults()
{
    const auto loaded = WatchList::load(
        R"({"format":"fatek-studio-watchlist","version":1,
            "tables":[{"items":[{"address":"R100"},{"address":"y3"}]}, {}]})");
    QVERIFY2(loaded.ok(), qPrintable(errorText(loaded)));
    QCOMPARE(loaded->tables.size(), 2);
    const WatchTableSpec &t = loaded->tables.at(0);
    QCOMPARE(t.name, QStringLiteral("Table 1"));
    QCOMPARE(t.intervalMs, 500);
    QCOMPARE(t.confirmWrites, true);
    QCOMPARE(t.items.size(), 2);
    QCOMPARE(t.items.at(0).address, addr("R100"));
    QCOMPARE(int(t.items.at(0).station), 1);
    QCOMPARE(t.items.at(0).format, DisplayFormat::Signed);
    QCOMPARE(t.items.at(0).swapWords, false);
    QCOMPARE(t.items.at(1).address, addr("Y3"));
    QCOMPARE(t.items.at(1).format, DisplayFormat::Bit);
    QCOMPARE(loaded->tables.at(1).name, QStringLiteral("Table 2"));
    QVERIFY(loaded->tables.at(1).items.isEmpty());

    const auto noTables
        = WatchList::load(R"({"format":"fatek-studio-watchlist","version":1,"tables":[]})");
    QVERIFY(noTables.ok());
    QVERIFY(noTables->tables.isEmpty());
}

void TestWatchList::loadErrors_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");

    const QString knownFormats
        = QStringLiteral("bit, unsigned, signed, hex, binary, bcd, float, ascii, double");
    QTest::newRow("array root") << QByteArray(
        "[]") << "The file is not a FATEK Studio watch list: it holds no JSON object.";
    QTest::newRow("no marker") << QByteArray(R"({"version":1,"tables":[]})")
                               << "The file is not a FATEK Studio watch list: \"format\" is not "
                                  "\"fatek-studio-watchlist\".";
    QTest::newRow("wrong marker") << QByteArray(
        R"({"format":"fatek-studio-project","version":1,"tables":[]})")
                                  << "The file is not a FATEK Studio watch list: \"format\" is not "
                                     "\"fatek-studio-watchlist\".";
    QTest::newRow("no version") << QByteArray(R"({"format":"fatek-studio-watchlist","tables":[]})")
                                << "The watch list has no valid \"version\" (expected 1).";
    QTest::newRow("version text") << QByteArray(
        R"({"format":"fatek-studio-watchlist","version":"1","tables":[]})")
                                  << "The watch list has no valid \"version\" (expected 1).";
    QTest::newRow("version 0") << QByteArray(
        R"({"format":"fatek-studio-watchlist","version":0,"tables":[]})")
                               << "The watch list has no valid \"version\" (expected 1).";
    QTest::newRow("version 1.5") << QByteArray(
        R"({"format":"fatek-studio-watchlist","version":1.5,"tables":[]})")
                                 << "The watch list has no valid \"version\" (expected 1).";
    QTest::newRow("version 3")
        << QByteArray(R"({"format":"fatek-studio-watchlist","version":3,"tables":[]})")
        << "The watch list is version 3, written by a newer FATEK Studio; this one reads "
           "version 2.";
    QTest::newRow("no tables") << QByteArray(R"({"format":"fatek-studio-watchlist","version":1})")
                               << "The watch list has no \"tables\" list.";
    QTest::newRow("tables object")
        << QByteArray(R"({"format":"fatek-studio-watchlist","version":1,"tables":{}})")
        << "The watch list has no \"tables\" list.";
    QTest::newRow("table not object")
        << QByteArray(R"({"format":"fatek-studio-watchlist","version":1,"tables":[5]})")
        << "table 1: a table must be a JSON object";
    QTest::newRow("interval small")
        << fileWithItems({}, R"(,"intervalMs":5)")
        << "table 1: line 1: \"intervalMs\" must be a whole number from 10 to 3600000";
    QTest::newRow("interval text")
        << fileWithItems({}, R"(,"intervalMs":"500")")
        << "table 1: line 1: \"intervalMs\" must be a whole number from 10 to 3600000";
    QTest::newRow("interval fraction")
        << fileWithItems({}, R"(,"intervalMs":500.5)")
        << "table 1: line 1: \"intervalMs\" must be a whole number from 10 to 3600000";
    QTest::newRow("confirm text") << fileWithItems({}, R"(,"confirmWrites":"yes")")
                                  << "table 1: line 1: \"confirmWrites\" must be true or false";
    QTest::newRow("table name number")
        << QByteArray(R"({"format":"fatek-studio-watchlist","version":1,"tables":[{"name":5}]})")
        << "table 1: line 1: \"name\" must be text";
    QTest::newRow("items object") << QByteArray(
        R"({"format":"fatek-studio-watchlist","version":1,"tables":[{"items":{}}]})")
                                  << "table 1: line 1: \"items\" must be a list";
    QTest::newRow("item not object")
        << fileWithItems("\"R100\"") << "table 1, item 1: an item must be a JSON object";
    QTest::newRow("no address") << fileWithItems(R"({"station":1})")
                                << "table 1, item 1: the \"address\" is missing";
    QTest::newRow("address number")
        << fileWithItems(R"({"address":100})")
        << "table 1, item 1: line 1: \"address\" must be text such as \"R100\"";
    QTest::newRow("address range")
        << fileWithItems(R"({"address":"R70000"})")
        << "table 1, item 1: line 1: address R70000 is out of range: R numbers go from 0 to 65535.";
    QTest::newRow("address unaligned")
        << fileWithItems(R"({"address":"WY4"})")
        << "table 1, item 1: line 1: address WY4 is not aligned: WY must start at a multiple "
           "of 8 (e.g. WY0).";
    QTest::newRow("unknown format")
        << fileWithItems(R"({"address":"R1"},{"address":"R2","format":"decimal"})")
        << "table 1, item 2: line 1: unknown format \"decimal\" (known: " + knownFormats + ")";
    QTest::newRow("format number") << fileWithItems(R"({"address":"R1","format":3})")
                                   << "table 1, item 1: line 1: \"format\" must be text";
    QTest::newRow("float on bit")
        << fileWithItems(R"({"address":"X0","format":"float"})")
        << "table 1, item 1: format \"float\" does not apply to X0 (input)";
    QTest::newRow("bit on register")
        << fileWithItems(R"({"address":"R7","format":"bit"})")
        << "table 1, item 1: format \"bit\" does not apply to R7 (data register)";
    QTest::newRow("float past end")
        << fileWithItems(R"({"address":"R65535","format":"float"})")
        << "table 1, item 1: format \"float\" on R65535 needs 2 elements: 2 elements "
           "from R65535 run past R65535, the last R.";
    QTest::newRow("double past end")
        << fileWithItems(R"({"address":"DR65534","format":"double"})")
        << "table 1, item 1: format \"double\" on DR65534 needs 2 elements: 2 elements "
           "from DR65534 run past DR65534, the last DR.";
    QTest::newRow("station 0")
        << fileWithItems(R"({"address":"R1","station":0})")
        << "table 1, item 1: line 1: \"station\" must be a whole number from 1 to 254";
    QTest::newRow("station 255")
        << fileWithItems(R"({"address":"R1","station":255})")
        << "table 1, item 1: line 1: \"station\" must be a whole number from 1 to 254";
    QTest::newRow("station text")
        << fileWithItems(R"({"address":"R1","station":"1"})")
        << "table 1, item 1: line 1: \"station\" must be a whole number from 1 to 254";
    QTest::newRow("swap text") << fileWithItems(R"({"address":"DR0","swapWords":"no"})")
                               << "table 1, item 1: line 1: \"swapWords\" must be true or false";
    QTest::newRow("name number") << fileWithItems(R"({"address":"R1","name":1})")
                                 << "table 1, item 1: line 1: \"name\" must be text";
    QTest::newRow("comment list") << fileWithItems(R"({"address":"R1","comment":[]})")
                                  << "table 1, item 1: line 1: \"comment\" must be text";
    // Issue 48: QJsonDocument keeps the last of two equal keys; the file says which line.
    QTest::newRow("duplicate item key")
        << fileWithItems("{\"address\":\"R1\",\n\"format\":\"hex\",\n\"format\":\"float\"}")
        << "line 3: duplicate key \"format\"";
    QTest::newRow("duplicate root key")
        << QByteArray(R"({"format":"fatek-studio-watchlist","version":1,"tables":[],)"
                      "\n\"version\":1}")
        << "line 2: duplicate key \"version\"";
    QTest::newRow("duplicate escaped key")
        << fileWithItems(R"({"address":"R1","name":"a","n\u0061me":"b"})")
        << "line 1: duplicate key \"name\"";
    QTest::newRow("nonfinite text")
        << fileWithItems(R"({"address":"R1","allowNonFinite":1})")
        << "table 1, item 1: line 1: \"allowNonFinite\" must be true or false";
    QByteArray many = R"({"address":"R1"})";
    for (int i = 1; i <= WatchList::MaxTableItems; ++i)
        many += R"(,{"address":"R1"})";
    QTest::newRow("too many items")
        << fileWithItems(many)
        << "table 1: 65537 items are more than one table holds (at most 65536)";
}

void TestWatchList::loadErrors()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const auto r = WatchList::load(json);
    QVERIFY(!r.ok());
    QCOMPARE(errorText(r), message);
}

// Issue 55: a misspelt key was ignored, so R200 was read as signed, station 1 polled instead of 2
// (another PLC on a multi-drop line), the interval stayed 500 and a table was silently empty. Each
// object of the file now refuses a key it does not know, with its place, its line and the key it
// most likely means.
void TestWatchList::unknownKeysRefused_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("message");
    const QByteArray head = "{\"format\":\"fatek-studio-watchlist\",\"version\":1,\n\"tables\":[\n";
    const QString item = QStringLiteral("unknown key \"%1\" (known: address, station, format, "
                                        "swapWords, allowNonFinite, name, comment, alarms, "
                                        "history); did you mean \"%2\"?");
    const QString table = QStringLiteral("unknown key \"%1\" (known: name, intervalMs, "
                                         "confirmWrites, items); did you mean \"%2\"?");
    const QString root = QStringLiteral("line 4: unknown key \"%1\" (known: format, version, "
                                        "tables, symbols)");
    QTest::newRow("fromat") << head + R"({"items":[{"address":"R100"},
{"address":"R200",
"fromat":"float"}]}]})"
                            << "table 1, item 2: line 5: " + item.arg("fromat", "format");
    QTest::newRow("staton") << head + R"({"items":[{"address":"DR10",
"staton":2}]}]})"
                            << "table 1, item 1: line 4: " + item.arg("staton", "station");
    QTest::newRow("swapwords") << head + R"({"items":[{"address":"DR10","format":"float",
"swapwords":true}]}]})"
                               << "table 1, item 1: line 4: " + item.arg("swapwords", "swapWords");
    QTest::newRow("intervalMS") << head + R"({"name":"Fast",
"intervalMS":50,"items":[{"address":"R1"}]}]})"
                                << "table 1: line 4: " + table.arg("intervalMS", "intervalMs");
    QTest::newRow("itmes, second table") << head + R"({"items":[{"address":"R1"}]},
{"name":"Second",
"itmes":[{"address":"R2"}]}]})"
                                         << "table 2: line 5: " + table.arg("itmes", "items");
    QTest::newRow("root tabels") << head + "],\n\"tabels\":[]}"
                                 << root.arg("tabels") + "; did you mean \"tables\"?";
    QTest::newRow("root, none near") << head + "],\n\"author\":\"me\"}" << root.arg("author");
    QTest::newRow("symbol nmae")
        << head + "],\"symbols\":[{\"address\":\"R1\",\n\"nmae\":\"Pump\"}]}"
        << "symbol 1: line 4: unknown key \"nmae\" (known: address, name, comment); did you mean "
           "\"name\"?";
    // A wrong type names its line as well.
    QTest::newRow("interval text") << head + "{\"name\":\"T\",\n\"intervalMs\":\"fast\"}]}"
                                   << "table 1: line 4: \"intervalMs\" must be a whole number "
                                      "from 10 to 3600000";
    QTest::newRow("station text")
        << head + "{\"items\":[{\"address\":\"R1\",\n\"station\":\"2\"}]}]}"
        << "table 1, item 1: line 4: \"station\" must be a whole "
           "number from 1 to 254";
}

void TestWatchList::unknownKeysRefused()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, message);
    const auto r = WatchList::load(json);
    QCOMPARE(errorText(r), message);
}

void TestWatchList::notJsonNamesLine()
{
    const auto r = WatchList::load(
        "{\n  \"format\": \"fatek-studio-watchlist\",\n  \"version\": 1,\n  oops\n}");
    QVERIFY(!r.ok());
    const QString message = errorText(r);
    QVERIFY2(message.startsWith(QStringLiteral("The file is not valid JSON: ")),
             qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral(" at line 4, column ")), qPrintable(message));

    const auto empty = WatchList::load(QByteArray());
    QVERIFY(!empty.ok());
    QVERIFY2(errorText(empty).contains(QStringLiteral("at line 1, column 1")),
             qPrintable(errorText(empty)));

    const auto truncated = WatchList::load(WatchList::save(sampleFile()).chopped(10));
    QVERIFY(!truncated.ok());
    QVERIFY(errorText(truncated).startsWith(QStringLiteral("The file is not valid JSON: ")));
}

void TestWatchList::errorNamesTableAndItem()
{
    const QByteArray json = R"({"format":"fatek-studio-watchlist","version":1,"tables":[
        {"name":"A","items":[{"address":"R1"}]},
        {"name":"B","items":[{"address":"R1"},{"address":"R2"},{"address":"R3"},{"address":"R4"},
                             {"address":"R-1"}]}]})";
    const auto r = WatchList::load(json);
    QVERIFY(!r.ok());
    QCOMPARE(errorText(r), QStringLiteral("table 2, item 5: line 4: invalid address \"R-1\": "
                                          "\"-1\" is not a decimal element number."));
    QCOMPARE(r.error().kind, ErrorKind::InvalidAddress);
}

void TestWatchList::saveToFileAndBack()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("plant.fwatch"));
    const WatchListFile file = sampleFile();
    const Status s = WatchList::saveToFile(file, path);
    QVERIFY2(s.ok(), s.ok() ? "" : s.error().text().c_str());
    const auto loaded = WatchList::loadFromFile(path);
    QVERIFY2(loaded.ok(), qPrintable(errorText(loaded)));
    QVERIFY(*loaded == file);

    // Overwriting an existing file with a valid list replaces it.
    WatchListFile smaller = file;
    smaller.tables.removeLast();
    QVERIFY(WatchList::saveToFile(smaller, path).ok());
    const auto reloaded = WatchList::loadFromFile(path);
    QVERIFY(reloaded.ok());
    QCOMPARE(reloaded->tables.size(), 2);
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("plant.fwatch")});
}

void TestWatchList::saveToFileRefusesInvalid()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("plant.fwatch"));
    QVERIFY(WatchList::saveToFile(sampleFile(), path).ok());
    QFile before(path);
    QVERIFY(before.open(QIODevice::ReadOnly));
    const QByteArray original = before.readAll();
    before.close();

    WatchListFile broken = sampleFile();
    broken.tables[1].items.append(entry("R1", DisplayFormat::Signed));
    broken.tables[1].items.append(entry("R2", DisplayFormat::Signed, 0));
    const Status s = WatchList::saveToFile(broken, path);
    QVERIFY(!s.ok());
    QCOMPARE(
        QString::fromStdString(s.error().text()),
        QStringLiteral(
            "Not saved: table 2, item 2: station 0 is broadcast (no PLC answers): use a station "
            "number 1..254"));

    WatchListFile badInterval = sampleFile();
    badInterval.tables[0].intervalMs = 5;
    const Status s2 = WatchList::saveToFile(badInterval, path);
    QVERIFY(!s2.ok());
    QCOMPARE(
        QString::fromStdString(s2.error().text()),
        QStringLiteral("Not saved: table 1: poll interval 5 ms is out of range (10..3600000 ms)"));

    QFile after(path);
    QVERIFY(after.open(QIODevice::ReadOnly));
    QCOMPARE(after.readAll(), original);
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("plant.fwatch")});
}

void TestWatchList::saveToFileUnwritable()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString missingDir = dir.filePath(QStringLiteral("no/such/dir/plant.fwatch"));
    const Status s = WatchList::saveToFile(sampleFile(), missingDir);
    QVERIFY(!s.ok());
    QVERIFY2(QString::fromStdString(s.error().text())
                 .startsWith(QStringLiteral("Cannot write ") + missingDir + ": "),
             s.error().text().c_str());
    QVERIFY(!QFile::exists(missingDir));

    // The target is a directory: nothing may replace it.
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("taken")));
    const QString taken = dir.filePath(QStringLiteral("taken"));
    const Status s2 = WatchList::saveToFile(sampleFile(), taken);
    QVERIFY(!s2.ok());
    QVERIFY(QFileInfo(taken).isDir());
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList());
}

void TestWatchList::loadFromFileErrors()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const auto missing = WatchList::loadFromFile(dir.filePath(QStringLiteral("missing.fwatch")));
    QVERIFY(!missing.ok());
    QVERIFY2(errorText(missing).startsWith(QStringLiteral("Cannot open ")),
             qPrintable(errorText(missing)));

    const QString path = dir.filePath(QStringLiteral("bad.fwatch"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(fileWithItems(R"({"address":"Q1"})"));
    f.close();
    const auto bad = WatchList::loadFromFile(path);
    QVERIFY(!bad.ok());
    QVERIFY2(errorText(bad).startsWith(
                 QStringLiteral("bad.fwatch: table 1, item 1: line 1: invalid address \"Q1\"")),
             qPrintable(errorText(bad)));
}

void TestWatchList::validateEntry()
{
    QVERIFY(WatchList::validateEntry(entry("R100", DisplayFormat::Double64)).ok());
    QVERIFY(WatchList::validateEntry(entry("R65532", DisplayFormat::Double64)).ok());
    QVERIFY(!WatchList::validateEntry(entry("R65533", DisplayFormat::Double64)).ok());
    QVERIFY(WatchList::validateEntry(entry("X9999", DisplayFormat::Bit, 254)).ok());
    WatchItemSpec e = entry("R1", DisplayFormat::Signed, 255);
    const Status s = WatchList::validateEntry(e);
    QVERIFY(!s.ok());
    QCOMPARE(QString::fromStdString(s.error().text()),
             QStringLiteral("station 255 is not valid: use a station number 1..254"));
    e = entry("R1", DisplayFormat::Signed);
    e.address.number = 70000; // built in code, not parsed: still checked
    QVERIFY(!WatchList::validateEntry(e).ok());
    QVERIFY(WatchList::validate(sampleFile()).ok());
}

void TestWatchList::csvPositional()
{
    const auto r
        = WatchList::importCsv("R100\nR101,2,hex,Pump,\"Speed, rpm\"\nX3,,,Start\nDR10,1,float\n");
    QVERIFY2(r.ok(), qPrintable(errorText(r)));
    QCOMPARE(r->size(), 4);
    QCOMPARE(r->at(0), entry("R100", DisplayFormat::Signed));
    QCOMPARE(r->at(1), entry("R101", DisplayFormat::Hex, 2, QStringLiteral("Pump"),
                             QStringLiteral("Speed, rpm")));
    QCOMPARE(r->at(2), entry("X3", DisplayFormat::Bit, 1, QStringLiteral("Start")));
    QCOMPARE(r->at(3), entry("DR10", DisplayFormat::Float32));

    // A name "address" in a data row does not make it a header.
    const auto named = WatchList::importCsv("R1,1,signed,address\n");
    QVERIFY2(named.ok(), qPrintable(errorText(named)));
    QCOMPARE(named->size(), 1);
    QCOMPARE(named->at(0).name, QStringLiteral("address"));
}

void TestWatchList::csvHeader()
{
    const auto r = WatchList::importCsv("Name;Address;Format\nTank;R100;float\n;Y0;\n");
    QVERIFY2(r.ok(), qPrintable(errorText(r)));
    QCOMPARE(r->size(), 2);
    QCOMPARE(r->at(0), entry("R100", DisplayFormat::Float32, 1, QStringLiteral("Tank")));
    QCOMPARE(r->at(1), entry("Y0", DisplayFormat::Bit));

    const auto full
        = WatchList::importCsv("address,station,format,name,comment,\nR5,7,unsigned,N,C,\n");
    QVERIFY2(full.ok(), qPrintable(errorText(full)));
    QCOMPARE(full->size(), 1);
    QCOMPARE(full->at(0),
             entry("R5", DisplayFormat::Unsigned, 7, QStringLiteral("N"), QStringLiteral("C")));

    // Rows copied from a watch table (issue 34): its value and quality columns are skipped.
    const auto copied = WatchList::importCsv(
        "address;name;value;format;quality;comment\nR1;Sine;0xFC18;hex;good, 0.4 s;wave\n");
    QVERIFY2(copied.ok(), qPrintable(errorText(copied)));
    QCOMPARE(copied->size(), 1);
    QCOMPARE(copied->at(0),
             entry("R1", DisplayFormat::Hex, 1, QStringLiteral("Sine"), QStringLiteral("wave")));
}

void TestWatchList::csvSemicolonsAndQuotes()
{
    // The first separator decides: here ';', so the comma belongs to the name.
    const auto r = WatchList::importCsv(
        "R100;1;signed;Level, tank;ok\r\n"
        "\"R101\" ; \"2\" ; \"ascii\" ; \"say \"\"hi\"\"\" ; \"two\nlines; really\"\r\n"
        "R102;;;;\r\n");
    QVERIFY2(r.ok(), qPrintable(errorText(r)));
    QCOMPARE(r->size(), 3);
    QCOMPARE(r->at(0), entry("R100", DisplayFormat::Signed, 1, QStringLiteral("Level, tank"),
                             QStringLiteral("ok")));
    QCOMPARE(r->at(1), entry("R101", DisplayFormat::Ascii, 2, QStringLiteral("say \"hi\""),
                             QStringLiteral("two\nlines; really")));
    QCOMPARE(r->at(2), entry("R102", DisplayFormat::Signed));

    // With ',' first, a ';' is ordinary text.
    const auto c = WatchList::importCsv("R100,1,signed,a;b\n");
    QVERIFY2(c.ok(), qPrintable(errorText(c)));
    QCOMPARE(c->at(0).name, QStringLiteral("a;b"));
}

void TestWatchList::csvRanges()
{
    const auto r = WatchList::importCsv("R100..R103,1,unsigned,Temp,zone\nWY0..WY32\nX0..X2,,,\n");
    QVERIFY2(r.ok(), qPrintable(errorText(r)));
    QCOMPARE(r->size(), 4 + 3 + 3);
    for (int i = 0; i < 4; ++i) {
        QCOMPARE(r->at(i).address, addr("R100").advanced(static_cast<std::uint32_t>(i)));
        QCOMPARE(r->at(i).format, DisplayFormat::Unsigned);
        QCOMPARE(r->at(i).name, QStringLiteral("Temp[%1]").arg(i));
        QCOMPARE(r->at(i).comment, QStringLiteral("zone"));
    }
    QCOMPARE(r->at(4).address, addr("WY0"));
    QCOMPARE(r->at(5).address, addr("WY16"));
    QCOMPARE(r->at(6).address, addr("WY32"));
    QCOMPARE(r->at(9).address, addr("X2"));
    QCOMPARE(r->at(9).name, QString());
    QCOMPARE(r->at(9).format, DisplayFormat::Bit);
}

void TestWatchList::csvSkipsBlankAndComments()
{
    const auto r = WatchList::importCsv(
        "# exported list\n\n   \naddress,name\n  # indented comment\nR1,One\n,,\n,\n\nR2,Two");
    QVERIFY2(r.ok(), qPrintable(errorText(r)));
    QCOMPARE(r->size(), 2);
    QCOMPARE(r->at(0).name, QStringLiteral("One"));
    QCOMPARE(r->at(1).name, QStringLiteral("Two"));
}

void TestWatchList::csvEncoding()
{
    const auto bom = WatchList::importCsv("\xEF\xBB\xBF"
                                          "address;name\nR1;F\xC3\xBCllstand\n");
    QVERIFY2(bom.ok(), qPrintable(errorText(bom)));
    QCOMPARE(bom->size(), 1);
    QCOMPARE(bom->at(0).name, QString::fromUtf8("F\xC3\xBCllstand"));

    const auto latin1 = WatchList::importCsv("R1;1;signed;F\xFCllstand\n");
    QVERIFY2(latin1.ok(), qPrintable(errorText(latin1)));
    QCOMPARE(latin1->at(0).name, QString::fromUtf8("F\xC3\xBCllstand"));
}

void TestWatchList::csvErrors_data()
{
    QTest::addColumn<QByteArray>("csv");
    QTest::addColumn<QString>("message");

    QTest::newRow("bad address")
        << QByteArray("R100\nR-1\n")
        << "line 2: invalid address \"R-1\": \"-1\" is not a decimal element number.";
    QTest::newRow("line after comments")
        << QByteArray("# c\n\nR100\nR70000")
        << "line 4: address R70000 is out of range: R numbers go from 0 to 65535.";
    QTest::newRow("line after quoted newline")
        << QByteArray("R100,1,signed,\"a\nb\"\nR70000")
        << "line 3: address R70000 is out of range: R numbers go from 0 to "
           "65535.";
    QTest::newRow("station 0") << QByteArray("R1,0")
                               << "line 1: station \"0\" is not valid: use a number from 1 to 254";
    QTest::newRow("station text") << QByteArray(
        "R1,one") << "line 1: station \"one\" is not valid: use a number from 1 to 254";
    QTest::newRow("station 300") << QByteArray(
        "R1;300") << "line 1: station \"300\" is not valid: use a number from 1 to 254";
    QTest::newRow("unknown format")
        << QByteArray("R1,1,decimal")
        << "line 1: unknown format \"decimal\" (known: bit, unsigned, signed, hex, binary, "
           "bcd, float, ascii, double)";
    QTest::newRow("format not applicable")
        << QByteArray("X0,1,float") << "line 1: format \"float\" does not apply to X0 (input)";
    QTest::newRow("range past end with double")
        << QByteArray("R65530..R65533,1,double")
        << "line 1: format \"double\" on R65533 needs 4 elements: 4 elements from R65533 run past "
           "R65535, the last R.";
    QTest::newRow("too many fields")
        << QByteArray("R1,1,signed,a,b,c")
        << "line 1: too many fields: at most 5 (address, station, format, name, comment)";
    QTest::newRow("unclosed quote")
        << QByteArray("R1\nR2,\"abc\nR3\n") << "line 2: a quoted field is not closed (missing \")";
    QTest::newRow("text after quote")
        << QByteArray("\"R100\"x,1") << "line 1: unexpected text after the quoted field \"R100\"";
    QTest::newRow("missing address")
        << QByteArray("R1\n,1,signed") << "line 2: the address is missing";
    QTest::newRow("too many items")
        << QByteArray("R0..R1023\n").repeated(65)
        << "line 65: 66560 items are more than one table holds (at most 65536)";
    QTest::newRow("reversed range")
        << QByteArray("R103..R100")
        << "line 1: range \"R103..R100\" runs backwards: write the lower address first "
           "(R100..R103).";
    QTest::newRow("unknown column")
        << QByteArray("address,foo\nR1,2")
        << "line 1: unknown column \"foo\" (known: address, station, format, name, comment)";
    QTest::newRow("duplicate column")
        << QByteArray("address;name;Name\nR1;a;b") << "line 1: column \"Name\" appears twice";
    QTest::newRow("more than header")
        << QByteArray("address\nR100,1") << "line 2: more fields than the header has columns";
    QTest::newRow("empty") << QByteArray() << "The CSV text holds no addresses to watch.";
    QTest::newRow("only comments")
        << QByteArray("# nothing\n\n") << "The CSV text holds no addresses to watch.";
    QTest::newRow("only header") << QByteArray("address,name\n")
                                 << "The CSV text holds no addresses to watch.";
}

void TestWatchList::csvErrors()
{
    QFETCH(QByteArray, csv);
    QFETCH(QString, message);
    const auto r = WatchList::importCsv(csv);
    QVERIFY(!r.ok());
    QCOMPARE(errorText(r), message);
}

void TestWatchList::expandRange_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("count");
    QTest::addColumn<QString>("first");
    QTest::addColumn<QString>("last");

    QTest::newRow("R100..R163") << "R100..R163" << 64 << "R100"
                                << "R163";
    QTest::newRow("X0..X15") << "X0..X15" << 16 << "X0"
                             << "X15";
    QTest::newRow("WY0..WY32") << "WY0..WY32" << 3 << "WY0"
                               << "WY32";
    QTest::newRow("DWM0..DWM64") << "DWM0..DWM64" << 3 << "DWM0"
                                 << "DWM64";
    QTest::newRow("DR0..DR4") << "DR0..DR4" << 3 << "DR0"
                              << "DR4";
    QTest::newRow("single") << "R100" << 1 << "R100"
                            << "R100";
    QTest::newRow("same both ends") << "R100..R100" << 1 << "R100"
                                    << "R100";
    QTest::newRow("number only end") << "R100..103" << 4 << "R100"
                                     << "R103";
    QTest::newRow("spaces and case") << "  r100 .. r103 " << 4 << "R100"
                                     << "R103";
    QTest::newRow("1024") << "R0..R1023" << 1024 << "R0"
                          << "R1023";
    QTest::newRow("to the end") << "R65530..R65535" << 6 << "R65530"
                                << "R65535";
}

void TestWatchList::expandRange()
{
    QFETCH(QString, text);
    QFETCH(int, count);
    QFETCH(QString, first);
    QFETCH(QString, last);
    const auto r = WatchList::expandRange(text);
    QVERIFY2(r.ok(), qPrintable(errorText(r)));
    QCOMPARE(r->size(), count);
    QCOMPARE(QString::fromStdString(r->first().toString()), first);
    QCOMPARE(QString::fromStdString(r->last().toString()), last);
    for (qsizetype i = 1; i < r->size(); ++i)
        QCOMPARE(r->at(i), r->at(0).advanced(static_cast<std::uint32_t>(i)));
}

void TestWatchList::expandRangeErrors_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");

    QTest::newRow("backwards")
        << "R103..R100"
        << "Range \"R103..R100\" runs backwards: write the lower address first (R100..R103).";
    QTest::newRow("too many")
        << "R0..R1024"
        << "Range \"R0..R1024\" has 1025 elements; at most 1024 fit in one range.";
    QTest::newRow("mixed")
        << "R100..D103"
        << "Range \"R100..D103\" mixes R100 and D103: both ends must be the same element type.";
    QTest::newRow("off step W")
        << "WY0..WY40"
        << "Range \"WY0..WY40\" does not end on a whole element: WY elements are 16 apart "
           "(WY0, WY16, ...).";
    QTest::newRow("off step DR")
        << "DR0..DR3"
        << "Range \"DR0..DR3\" does not end on a whole element: DR elements are 2 apart "
           "(DR0, DR2, ...).";
    QTest::newRow("no end")
        << "R100.."
        << "Incomplete range \"R100..\": write it as first..last, e.g. R100..R163.";
    QTest::newRow("no start")
        << "..R5"
        << "Incomplete range \"..R5\": write it as first..last, e.g. R100..R163.";
    QTest::newRow("bad start")
        << "R-1..R5"
        << "Invalid address \"R-1\": \"-1\" is not a decimal element number.";
    QTest::newRow("end out of range")
        << "R65530..R70000"
        << "Address R70000 is out of range: R numbers go from 0 to 65535.";
    QTest::newRow("three dots")
        << "R1...R5"
        << "Invalid address \".R5\": it must start with an element type such as "
           "R, X or DWM.";
    QTest::newRow("empty") << ""
                           << "Empty address: type an element such as R12 or X0.";
}

void TestWatchList::expandRangeErrors()
{
    QFETCH(QString, text);
    QFETCH(QString, message);
    const auto r = WatchList::expandRange(text);
    QVERIFY(!r.ok());
    QCOMPARE(errorText(r), message);
    QCOMPARE(r.error().kind, ErrorKind::InvalidAddress);
}

QTEST_GUILESS_MAIN(TestWatchList)
#include "tst_watchlist.moc"
