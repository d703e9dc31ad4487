// DataLogger: the CSV data log of watch values (header, formats, quality, append, file errors).
#include "core/watch/datalogger.h"

#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <tuple>

using namespace Fatek;

namespace {

WatchItemSpec item(const char *address, DisplayFormat format, const QString &name = {},
                   quint8 station = 1)
{
    WatchItemSpec s;
    s.address = Address::parse(address).value();
    s.format = format;
    s.name = name;
    s.station = station;
    return s;
}

DataLogger::Cell good(std::uint64_t raw)
{
    return {raw, DataLogger::Quality::Good, {}};
}

QStringList readLines(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QByteArray data = f.readAll();
    if (data.startsWith("\xEF\xBB\xBF")) // the byte order mark a new log starts with
        data.remove(0, 3);
    return QString::fromUtf8(data).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestDataLogger : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void timestampHasMillisecondsAndOffset();
    void headerAndFormattedValues();
    void staleValuesAreNeverWrittenAsFresh();
    void sameAddressInTwoFormatsHasTwoHeaders();
    void outageRowNamesTheReasonOnce();
    void appendKeepsHeaderOnce();
    void appendRefusesOtherColumns();
    void newLogStartsWithTheMark();
    void appendKeepsTheFilesLineEnds();
    void appendToALogWithoutTheMark();
    void quotesCellsWithSeparators();
    void unwritablePaths();
    void diskFull();

private:
    QTemporaryDir m_dir;
};

void TestDataLogger::timestampHasMillisecondsAndOffset()
{
    const QDateTime utc(QDate(2026, 11, 23), QTime(9, 35, 31, 458), Qt::UTC);
    const QString text = DataLogger::timestampText(utc);
    static const QRegularExpression iso(
        QStringLiteral("^\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\d\\.458[+-]\\d\\d:\\d\\d$"));
    QVERIFY2(iso.match(text).hasMatch(), qPrintable(text));
    // The text names the same instant.
    QCOMPARE(QDateTime::fromString(text, Qt::ISODateWithMs).toUTC(), utc);
}

void TestDataLogger::headerAndFormattedValues()
{
    const QString path = m_dir.filePath(QStringLiteral("values.csv"));
    DataLogger log;
    const QList<WatchItemSpec> items{item("R1", DisplayFormat::Signed, QStringLiteral("Sine")),
                                     item("R2", DisplayFormat::Hex), item("Y0", DisplayFormat::Bit),
                                     item("R10", DisplayFormat::Float32, {}, 3)};
    QVERIFY(log.open(path, items));
    QCOMPARE(log.columns().size(), 6);
    const QDateTime t0 = QDateTime::currentDateTime();
    // 1.5f = 0x3FC00000: R10 holds the low word, R11 the high word.
    QVERIFY(log.writeRow(t0, {good(0xFFFF), good(0x1A), good(1), good(0x3FC00000)}));
    QVERIFY(log.writeRow(t0.addMSecs(500), {good(1000), good(0xFFFF), good(0), good(0)}));
    QCOMPARE(log.rowCount(), 2);
    QVERIFY(log.close());

    const QStringList lines = readLines(path);
    QCOMPARE(lines.size(), 3);
    QCOMPARE(lines.at(0), QStringLiteral("timestamp,Sine (R1),R2,Y0,R10@3,status"));
    QCOMPARE(lines.at(1).section(QLatin1Char(','), 1), QStringLiteral("-1,0x001A,1,1.5,ok"));
    QCOMPARE(lines.at(2).section(QLatin1Char(','), 1), QStringLiteral("1000,0xFFFF,0,0,ok"));
    QCOMPARE(lines.at(1).section(QLatin1Char(','), 0, 0), DataLogger::timestampText(t0));
}

void TestDataLogger::staleValuesAreNeverWrittenAsFresh()
{
    const QString path = m_dir.filePath(QStringLiteral("stale.csv"));
    DataLogger log;
    QVERIFY(
        log.open(path, {item("R0", DisplayFormat::Unsigned), item("R1", DisplayFormat::Signed)}));
    const QDateTime now = QDateTime::currentDateTime();
    QVERIFY(
        log.writeRow(now, {good(5), {77, DataLogger::Quality::Stale, QStringLiteral("timeout")}}));
    QVERIFY(log.writeRow(now, {{3, DataLogger::Quality::Error, QStringLiteral("PLC error A")}}));
    QVERIFY(log.close());
    const QStringList lines = readLines(path);
    QCOMPARE(lines.size(), 3);
    QCOMPARE(lines.at(1).section(QLatin1Char(','), 1), QStringLiteral("5,,stale R1 (timeout)"));
    // The value cells only: the timestamp cell may hold "77" (milliseconds .770-.779, .077, ...).
    QVERIFY(!lines.at(1).section(QLatin1Char(','), 1).contains(QLatin1String("77")));
    // Several problems: the status cell holds a ';' and is quoted for semicolon-locale
    // spreadsheets.
    QCOMPARE(lines.at(2).section(QLatin1Char(','), 1),
             QStringLiteral(",,\"error R0 (PLC error A); missing R1\""));
}

void TestDataLogger::sameAddressInTwoFormatsHasTwoHeaders()
{
    // A technician watches R0 as a number and as hex: the columns must not both read "R0".
    const QList<WatchItemSpec> items{
        item("R0", DisplayFormat::Signed), item("R0", DisplayFormat::Hex),
        item("R1", DisplayFormat::Signed), item("R1", DisplayFormat::Signed),
        item("R0", DisplayFormat::Hex, QStringLiteral("Level"))};
    const QString header = DataLogger::headerLine(items);
    QCOMPARE(header, QStringLiteral("timestamp,R0 [signed],R0 [hex],R1 [signed],R1 [signed] #2,"
                                    "Level (R0),status"));
    const QStringList cells = header.split(QLatin1Char(','));
    QCOMPARE(QSet<QString>(cells.cbegin(), cells.cend()).size(), cells.size());

    const QString path = m_dir.filePath(QStringLiteral("formats.csv"));
    DataLogger log;
    QVERIFY(log.open(path, items.mid(0, 2)));
    QCOMPARE(log.columns(), (QStringList{QStringLiteral("timestamp"), QStringLiteral("R0 [signed]"),
                                         QStringLiteral("R0 [hex]"), QStringLiteral("status")}));
    QVERIFY(log.writeRow(QDateTime::currentDateTime(), {good(0xFFFE), good(0xFFFE)}));
    QVERIFY(log.close());
    const QStringList lines = readLines(path);
    QCOMPARE(lines.size(), 2);
    QCOMPARE(lines.at(0), QStringLiteral("timestamp,R0 [signed],R0 [hex],status"));
    QCOMPARE(lines.at(1).section(QLatin1Char(','), 1), QStringLiteral("-2,0xFFFE,ok"));
    // No clash, no change: one item per address keeps the plain header.
    QCOMPARE(
        DataLogger::headerLine({item("R0", DisplayFormat::Hex), item("R1", DisplayFormat::Bcd)}),
        QStringLiteral("timestamp,R0,R1,status"));
}

void TestDataLogger::outageRowNamesTheReasonOnce()
{
    const QList<WatchItemSpec> items{
        item("R0", DisplayFormat::Signed), item("R0", DisplayFormat::Hex),
        item("R1", DisplayFormat::Signed), item("Y0", DisplayFormat::Bit)};
    const QString down = QStringLiteral("no link: connection refused");
    const QDateTime now = QDateTime::currentDateTime();
    // The link is down: every item stale for one reason; the reason is written once.
    QList<DataLogger::Cell> cells(4, DataLogger::Cell{7, DataLogger::Quality::Stale, down});
    const QString row = DataLogger::rowLine(now, items, cells);
    QCOMPARE(row.section(QLatin1Char(','), 1),
             QStringLiteral(",,,,stale all items (no link: connection refused)"));
    QCOMPARE(row.count(down), 1);
    // Two items late for one reason, one refused: each cause once, naming its items.
    cells = {good(5),
             {0, DataLogger::Quality::Stale, QStringLiteral("timeout")},
             {0, DataLogger::Quality::Stale, QStringLiteral("timeout")},
             {0, DataLogger::Quality::Error, QStringLiteral("PLC error A")}};
    QCOMPARE(DataLogger::rowLine(now, items, cells).section(QLatin1Char(','), 1),
             QStringLiteral("5,,,,\"stale R0 [hex], R1 (timeout); error Y0 (PLC error A)\""));
}

void TestDataLogger::appendKeepsHeaderOnce()
{
    const QString path = m_dir.filePath(QStringLiteral("append.csv"));
    const QList<WatchItemSpec> items{item("D5", DisplayFormat::Unsigned)};
    for (int run = 0; run < 2; ++run) {
        DataLogger log;
        QVERIFY(log.open(path, items));
        QVERIFY(
            log.writeRow(QDateTime::currentDateTime(), {good(static_cast<std::uint64_t>(run))}));
    } // the destructor flushes and closes
    const QStringList lines = readLines(path);
    QCOMPARE(lines.size(), 3);
    QCOMPARE(lines.at(0), QStringLiteral("timestamp,D5,status"));
    QVERIFY(lines.at(1).endsWith(QLatin1String(",0,ok")));
    QVERIFY(lines.at(2).endsWith(QLatin1String(",1,ok")));
}

void TestDataLogger::appendRefusesOtherColumns()
{
    const QString path = m_dir.filePath(QStringLiteral("other.csv"));
    {
        DataLogger log;
        QVERIFY(log.open(path, {item("R0", DisplayFormat::Signed)}));
    }
    DataLogger log;
    const Status s = log.open(path, {item("R1", DisplayFormat::Signed)});
    QVERIFY(!s);
    QVERIFY2(QString::fromStdString(s.error().text()).contains(QLatin1String("other columns")),
             s.error().text().c_str());
    QVERIFY(!log.isOpen());
    QCOMPARE(readLines(path).size(), 1);
}

void TestDataLogger::newLogStartsWithTheMark()
{
    // Excel on Windows reads the file as UTF-8 only with the mark; CRLF when asked.
    const QString path = m_dir.filePath(QStringLiteral("windows.csv"));
    const QList<WatchItemSpec> items{item("R0", DisplayFormat::Signed, QString::fromUtf8("液位"))};
    DataLogger log;
    QVERIFY(log.open(path, items, CsvFile::LineEnd::CrLf));
    QCOMPARE(log.lineEnd(), CsvFile::LineEnd::CrLf);
    QVERIFY(log.writeRow(QDateTime::currentDateTime(), {good(7)}));
    QVERIFY(log.close());
    const QByteArray data = readAll(path);
    QVERIFY2(data.startsWith("\xEF\xBB\xBF"
                             "timestamp,\xE6\xB6\xB2\xE4\xBD\x8D (R0),status\r\n"),
             data.constData());
    QVERIFY2(data.endsWith(",7,ok\r\n"), data.constData());
    QCOMPARE(data.count('\n'), 2);
    QCOMPARE(data.count("\r\n"), 2);

    const QString lf = m_dir.filePath(QStringLiteral("lf.csv"));
    QVERIFY(log.open(lf, items));
    QVERIFY(log.close());
    QCOMPARE(readAll(lf), QByteArray("\xEF\xBB\xBF"
                                     "timestamp,\xE6\xB6\xB2\xE4\xBD\x8D (R0),status\n"));
}

void TestDataLogger::appendKeepsTheFilesLineEnds()
{
    // An existing log is appended to with its own line ends whatever is asked now, its header
    // (after the mark, before "\r\n") is read as the same columns, and it never gets a second
    // mark.
    const QList<WatchItemSpec> items{item("D5", DisplayFormat::Unsigned)};
    for (const auto &[name, first, later] :
         {std::tuple{"keep-crlf.csv", CsvFile::LineEnd::CrLf, CsvFile::LineEnd::Lf},
          std::tuple{"keep-lf.csv", CsvFile::LineEnd::Lf, CsvFile::LineEnd::CrLf}}) {
        const QString path = m_dir.filePath(QLatin1String(name));
        for (int run = 0; run < 3; ++run) {
            DataLogger log;
            const Status s = log.open(path, items, run == 0 ? first : later);
            QVERIFY2(s, s ? "" : s.error().text().c_str());
            QCOMPARE(log.lineEnd(), first);
            QVERIFY(log.writeRow(QDateTime::currentDateTime(),
                                 {good(static_cast<std::uint64_t>(run))}));
        }
        const QByteArray data = readAll(path);
        QCOMPARE(data.count("\xEF\xBB\xBF"), 1);
        QVERIFY(data.startsWith("\xEF\xBB\xBF"));
        QCOMPARE(data.count('\n'), 4);
        QCOMPARE(data.count("\r\n"), first == CsvFile::LineEnd::CrLf ? 4 : 0);
        const QStringList lines = readLines(path);
        QCOMPARE(lines.size(), 4);
        QVERIFY2(lines.at(3).endsWith(first == CsvFile::LineEnd::CrLf ? QLatin1String(",2,ok\r")
                                                                      : QLatin1String(",2,ok")),
                 qPrintable(lines.at(3)));
    }
}

void TestDataLogger::appendToALogWithoutTheMark()
{
    // A log an earlier version wrote (no mark) is appended to as it is: no mark in the middle.
    const QString path = m_dir.filePath(QStringLiteral("old.csv"));
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        QVERIFY(f.write("timestamp,R0,status\n2026-11-23T10:35:31.458+01:00,1,ok\n") > 0);
    }
    DataLogger log;
    QVERIFY(log.open(path, {item("R0", DisplayFormat::Signed)}, CsvFile::LineEnd::CrLf));
    QVERIFY(log.writeRow(QDateTime::currentDateTime(), {good(2)}));
    QVERIFY(log.close());
    const QByteArray data = readAll(path);
    QVERIFY(data.startsWith("timestamp,R0,status\n"));
    QVERIFY(!data.contains("\xEF\xBB\xBF"));
    QVERIFY(!data.contains('\r'));
    QVERIFY(data.endsWith(",2,ok\n"));
}

void TestDataLogger::quotesCellsWithSeparators()
{
    const QString path = m_dir.filePath(QStringLiteral("quoted.csv"));
    DataLogger log;
    QVERIFY(log.open(path, {item("R0", DisplayFormat::Ascii, QStringLiteral("Tank, \"A\""))}));
    QVERIFY(log.writeRow(QDateTime::currentDateTime(), {good(0x2C41)})); // ",A"
    QVERIFY(log.close());
    const QStringList lines = readLines(path);
    QCOMPARE(lines.at(0), QStringLiteral("timestamp,\"Tank, \"\"A\"\" (R0)\",status"));
    QVERIFY2(lines.at(1).endsWith(QLatin1String(",\",A\",ok")), qPrintable(lines.at(1)));
}

void TestDataLogger::unwritablePaths()
{
    DataLogger log;
    const QList<WatchItemSpec> items{item("R0", DisplayFormat::Signed)};
    Status s = log.open(m_dir.filePath(QStringLiteral("missing/dir/x.csv")), items);
    QVERIFY(!s);
    QVERIFY(QString::fromStdString(s.error().text()).contains(QLatin1String("does not exist")));
    s = log.open(m_dir.path(), items);
    QVERIFY(!s);
    QVERIFY(QString::fromStdString(s.error().text()).contains(QLatin1String("folder")));
    s = log.open(m_dir.filePath(QStringLiteral("empty.csv")), {});
    QVERIFY(!s);
    // Writing without an open log is an error, not a crash.
    QVERIFY(!log.writeRow(QDateTime::currentDateTime(), {good(1)}));
#ifdef Q_OS_UNIX
    const QString readOnly = m_dir.filePath(QStringLiteral("readonly.csv"));
    {
        QFile f(readOnly);
        QVERIFY(f.open(QIODevice::WriteOnly));
    }
    QFile::setPermissions(readOnly, QFileDevice::ReadOwner);
    if (QFileInfo(readOnly).isWritable())
        QSKIP("running as root: permissions are not enforced");
    s = log.open(readOnly, items);
    QVERIFY(!s);
    QVERIFY(QString::fromStdString(s.error().text()).contains(QLatin1String("Cannot open")));
#endif
}

void TestDataLogger::diskFull()
{
#ifdef Q_OS_LINUX
    if (!QFileInfo::exists(QStringLiteral("/dev/full")))
        QSKIP("no /dev/full");
    DataLogger log;
    const Status s = log.open(QStringLiteral("/dev/full"), {item("R0", DisplayFormat::Signed)});
    // The header flush already fails: the error names the cause and the log is closed.
    QVERIFY(!s);
    QVERIFY2(QString::fromStdString(s.error().text()).contains(QLatin1String("Logging stopped")),
             s.error().text().c_str());
    QVERIFY(!log.isOpen());
    QVERIFY(!log.writeRow(QDateTime::currentDateTime(), {good(1)}));
#else
    QSKIP("needs /dev/full");
#endif
}

QTEST_GUILESS_MAIN(TestDataLogger)
#include "tst_datalogger.moc"
