// fatek-cli end to end: the built executable run with QProcess, against its embedded simulator
// (--sim) and against the independent Python reference PLC (tests/reference/fatekref.py) over TCP
// and UDP in both protocols.
#include "testutil.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>

#ifdef Q_OS_UNIX
#include <csignal>
#include <sys/stat.h>
#endif
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>

namespace {

// The shared result of a program run (lines() drops Windows' CR), with any line as JSON.
struct Run : TestUtil::ProgramRun
{
    QJsonObject json(int line = 0) const
    {
        const QStringList l = lines();
        if (line >= l.size())
            return {};
        return QJsonDocument::fromJson(l.at(line).toUtf8()).object();
    }
};

Run runCli(const QStringList &arguments, int timeoutMs = 30000)
{
    QProcess p;
    p.start(QStringLiteral(FATEK_CLI_PATH), arguments);
    Run r;
    if (!p.waitForStarted(10000))
        return r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        r.err = QStringLiteral("fatek-cli did not end within %1 ms").arg(timeoutMs);
        return r;
    }
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

QJsonArray ints(std::initializer_list<qint64> values)
{
    QJsonArray a;
    for (qint64 v : values)
        a.append(v);
    return a;
}

QStringList sim(const QStringList &args)
{
    return QStringList{QStringLiteral("--sim")} + args;
}

const QString fullDevice = QStringLiteral("/dev/full");
const QString noSpace = QStringLiteral("No space left on device");

bool isCharacterDevice(const QString &path)
{
#ifdef Q_OS_UNIX
    struct stat st = {};
    return ::stat(QFile::encodeName(path).constData(), &st) == 0 && S_ISCHR(st.st_mode);
#else
    Q_UNUSED(path);
    return false;
#endif
}

// fatek-cli with its standard output into `path` (a file or a device).
Run runCliInto(const QString &path, const QStringList &arguments)
{
    QProcess p;
    p.setStandardOutputFile(path);
    p.start(QStringLiteral(FATEK_CLI_PATH), arguments);
    Run r;
    if (!p.waitForStarted(10000))
        return r;
    if (!p.waitForFinished(30000)) {
        p.kill();
        p.waitForFinished();
        r.err = QStringLiteral("fatek-cli did not end");
        return r;
    }
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

QByteArray fileBytes(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("(unreadable)");
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size()
           && f.flush();
}

// Every line on stderr is fatek-cli's own: no Qt warning slipped through.
bool onlyOwnLines(const QString &err)
{
    const QStringList lines = err.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    return std::all_of(lines.begin(), lines.end(), [](const QString &line) {
        return line.startsWith(QLatin1String("fatek-cli: "));
    });
}

} // namespace

#define RUN_OK(r)                                                                                  \
    QVERIFY2((r).code == 0,                                                                        \
             qPrintable(QStringLiteral("exit %1: %2 %3").arg((r).code).arg((r).err, (r).out)))

class TestCli : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void help();
    void usageErrors_data();
    void usageErrors();
    void simStatus();
    void simWriteReadRoundTrip();
    void simWriteTypedValues();
    void simDiscreteSetThenRead();
    void simDisableForced();
    void simLoopback();
    void simMonitorThreeCycles();
    void simMonitorTable();
    void simMonitorStopsOnInterrupt();
    void simRawFrame();
    void simJsonShape();
    void simCsvShape();
    void simCsvFilesForExcel();
    void simMixedRead();
    void completions();
    void simReadSplitsAndFormats();
    void simMonitorNames();
    void plcErrorExit4();
    void linkFailureExit3();
    void readOnlyExit5();
    void broadcastUnderAutoExit2();

    void filesOnFullDevice_data();
    void filesOnFullDevice();
    void filesOnFullDisk_data();
    void filesOnFullDisk();
    void monitorLogOnFullDevice();
    void monitorLogFillsTheDisk();
    void outputOnFullDevice_data();
    void outputOnFullDevice();
    void outputIntoClosedPipe();

    void reference_data();
    void reference();
    void referenceAutoDetect();
    void referenceReadOnlyKeepsValue();
    void referenceWriteTypedValues();
    void referenceMonitorCsvLog();

private:
    QStringList ref(const QString &medium, const QString &protocol) const;

    QProcess m_ref;
    quint16 m_refTcp = 0;
    quint16 m_refUdp = 0;
    QString m_refProblem;
};

void TestCli::initTestCase()
{
    const QString python = QStandardPaths::findExecutable(QStringLiteral("python3"));
    if (python.isEmpty()) {
        m_refProblem = QStringLiteral("python3 not found on PATH");
        return;
    }
    m_ref.setProgram(python);
    m_ref.setArguments({QStringLiteral(FATEK_REFERENCE_PY), QStringLiteral("serve"),
                        QStringLiteral("--tcp"), QStringLiteral("0"), QStringLiteral("--udp"),
                        QStringLiteral("0")});
    m_ref.start();
    if (!m_ref.waitForStarted(10000)) {
        m_refProblem = QStringLiteral("the reference server did not start");
        return;
    }
    static const QRegularExpression listening(QStringLiteral("listening (tcp|udp) (\\d+)"));
    QByteArray seen;
    while ((m_refTcp == 0 || m_refUdp == 0) && m_ref.waitForReadyRead(10000)) {
        seen += m_ref.readAllStandardOutput();
        for (const QString &line : QString::fromUtf8(seen).split(QLatin1Char('\n'))) {
            const auto m = listening.match(line);
            if (!m.hasMatch())
                continue;
            (m.captured(1) == QLatin1String("tcp") ? m_refTcp : m_refUdp)
                = static_cast<quint16>(m.captured(2).toUInt());
        }
    }
    if (m_refTcp == 0 || m_refUdp == 0)
        m_refProblem = QStringLiteral("the reference server did not say where it listens: ")
                       + QString::fromUtf8(seen);
}

void TestCli::cleanupTestCase()
{
    if (m_ref.state() != QProcess::NotRunning) {
        m_ref.kill();
        m_ref.waitForFinished(5000);
    }
}

QStringList TestCli::ref(const QString &medium, const QString &protocol) const
{
    const quint16 port = medium == QLatin1String("tcp") ? m_refTcp : m_refUdp;
    return {QStringLiteral("--") + medium,
            QStringLiteral("127.0.0.1:%1").arg(port),
            QStringLiteral("--protocol"),
            protocol,
            QStringLiteral("--json"),
            QStringLiteral("--timeout"),
            QStringLiteral("1000"),
            QStringLiteral("--retries"),
            QStringLiteral("1")};
}

void TestCli::help()
{
    const Run r = runCli({QStringLiteral("--help")});
    RUN_OK(r);
    QVERIFY(r.out.contains(QLatin1String("Usage: fatek-cli")));
    QVERIFY(r.out.contains(QLatin1String("monitor ADDR")));
    const Run v = runCli({QStringLiteral("--version")});
    RUN_OK(v);
    QVERIFY(v.out.startsWith(QLatin1String("fatek-cli ")));
}

void TestCli::usageErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("no link") << QStringList{QStringLiteral("status")}
                             << QStringLiteral("No link given");
    QTest::newRow("no command") << QStringList{QStringLiteral("--sim")}
                                << QStringLiteral("No command");
    QTest::newRow("unknown command")
        << sim({QStringLiteral("explode")}) << QStringLiteral("Unknown command");
    QTest::newRow("unknown option")
        << sim({QStringLiteral("--frobnicate"), QStringLiteral("status")})
        << QStringLiteral("Unknown option --frobnicate");
    QTest::newRow("two links") << QStringList{QStringLiteral("--sim"), QStringLiteral("--tcp"),
                                              QStringLiteral("127.0.0.1"), QStringLiteral("status")}
                               << QStringLiteral("only one");
    QTest::newRow("address out of range")
        << sim({QStringLiteral("read"), QStringLiteral("R70000")}) << QStringLiteral("R70000");
    QTest::newRow("16-bit overflow")
        << sim({QStringLiteral("write"), QStringLiteral("R100"), QStringLiteral("70000")})
        << QStringLiteral("16-bit");
    QTest::newRow("discrete value")
        << sim({QStringLiteral("write"), QStringLiteral("Y0"), QStringLiteral("2")})
        << QStringLiteral("0, 1, on or off");
    QTest::newRow("float into an integer register")
        << sim({QStringLiteral("write"), QStringLiteral("R100"), QStringLiteral("1.5")})
        << QStringLiteral("R100: \"1.5\" is not a number");
    QTest::newRow("unknown write format")
        << sim({QStringLiteral("write"), QStringLiteral("R100:real"), QStringLiteral("1.5")})
        << QStringLiteral("Unknown format \"real\"");
    QTest::newRow("write format that does not fit")
        << sim({QStringLiteral("write"), QStringLiteral("Y0:float"), QStringLiteral("1.5")})
        << QStringLiteral("does not apply to Y0");
    QTest::newRow("float past the last register")
        << sim({QStringLiteral("write"), QStringLiteral("R65535:float"), QStringLiteral("1.5")})
        << QStringLiteral("needs 2 elements");
    // More than one request carries is read in several (issue 32), up to a monitor's limit.
    QTest::newRow("count too big")
        << sim({QStringLiteral("read"), QStringLiteral("R0"), QStringLiteral("1025")})
        << QStringLiteral("1..1024");
    QTest::newRow("set on register")
        << sim({QStringLiteral("set"), QStringLiteral("R0")}) << QStringLiteral("discretes");
    QTest::newRow("bad raw hex") << sim(
        {QStringLiteral("raw"), QStringLiteral("--hex"), QStringLiteral("0G")})
                                 << QStringLiteral("hex");
    QTest::newRow("bad port") << QStringList{QStringLiteral("--tcp"), QStringLiteral("h:99999"),
                                             QStringLiteral("status")}
                              << QStringLiteral("HOST:PORT");
    QTest::newRow("read from broadcast") << sim({QStringLiteral("--station"), QStringLiteral("0"),
                                                 QStringLiteral("read"), QStringLiteral("R0")})
                                         << QStringLiteral("broadcast");
    QTest::newRow("endless monitor in a chain")
        << sim({QStringLiteral("monitor"), QStringLiteral("R0"), QStringLiteral("--then"),
                QStringLiteral("status")})
        << QStringLiteral("--cycles");
    QTest::newRow("option of another command")
        << sim({QStringLiteral("status"), QStringLiteral("--cycles"), QStringLiteral("3")})
        << QStringLiteral("monitor");
    QTest::newRow("names for read") << sim({QStringLiteral("read"), QStringLiteral("R0"),
                                            QStringLiteral("--names"), QStringLiteral("names.csv")})
                                    << QStringLiteral("monitor");
    // --crlf is for the CSV files a command writes: read writes none (its --csv is stdout).
    QTest::newRow("crlf without a CSV file")
        << sim({QStringLiteral("--crlf"), QStringLiteral("read"), QStringLiteral("R0")})
        << QStringLiteral("--crlf only applies to");
}

void TestCli::usageErrors()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const Run r = runCli(args);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(r.out.isEmpty());

    // With --json the error also comes on stdout as {"error":...,"code":2}.
    const Run j = runCli(QStringList{QStringLiteral("--json")} + args);
    QCOMPARE(j.code, 2);
    QCOMPARE(j.json().value(QStringLiteral("code")).toInt(), 2);
    QVERIFY(j.json().value(QStringLiteral("error")).toString().contains(message));
}

void TestCli::simStatus()
{
    const Run r = runCli(sim({QStringLiteral("status")}));
    RUN_OK(r);
    QVERIFY(r.out.contains(QRegularExpression(QStringLiteral("mode\\s+RUN"))));
    QVERIFY(r.out.contains(QRegularExpression(QStringLiteral("battery low\\s+no"))));
    QVERIFY(r.out.contains(QRegularExpression(QStringLiteral("OS version\\s+V3.1"))));

    const Run j = runCli(sim({QStringLiteral("--json"), QStringLiteral("status")}));
    RUN_OK(j);
    const QJsonObject o = j.json();
    QCOMPARE(o.value(QStringLiteral("running")).toBool(), true);
    QCOMPARE(o.value(QStringLiteral("status1")).toInt(), 1);
    QCOMPARE(o.value(QStringLiteral("protocol")).toString(), QStringLiteral("FACON"));
    const QJsonObject d = o.value(QStringLiteral("detail")).toObject();
    QCOMPARE(d.value(QStringLiteral("ladderSize")).toInt(), 13184);
    QCOMPARE(d.value(QStringLiteral("osVersion")).toString(), QStringLiteral("V3.1"));
}

void TestCli::simWriteReadRoundTrip()
{
    const Run r
        = runCli(sim({QStringLiteral("--json"), QStringLiteral("write"), QStringLiteral("R100"),
                      QStringLiteral("1234"), QStringLiteral("-2"), QStringLiteral("0xBEEF"),
                      QStringLiteral("--then"), QStringLiteral("read"), QStringLiteral("R100"),
                      QStringLiteral("3")}));
    RUN_OK(r);
    QCOMPARE(r.lines().size(), 2);
    QCOMPARE(r.json(0).value(QStringLiteral("written")).toArray(), ints({1234, 65534, 48879}));
    QCOMPARE(r.json(1).value(QStringLiteral("values")).toArray(), ints({1234, 65534, 48879}));

    // Without the write the simulator starts from zero: the round trip really read what was
    // written.
    const Run fresh = runCli(sim({QStringLiteral("--json"), QStringLiteral("read"),
                                  QStringLiteral("R100"), QStringLiteral("3")}));
    RUN_OK(fresh);
    QCOMPARE(fresh.json().value(QStringLiteral("values")).toArray(), ints({0, 0, 0}));

    const Run dr
        = runCli(sim({QStringLiteral("--json"), QStringLiteral("write"), QStringLiteral("DR200"),
                      QStringLiteral("-100000"), QStringLiteral("--then"), QStringLiteral("read"),
                      QStringLiteral("R200"), QStringLiteral("2")}));
    RUN_OK(dr);
    // -100000 = 0xFFFE7960: low word first in R200.
    QCOMPARE(dr.json(1).value(QStringLiteral("values")).toArray(), ints({0x7960, 0xFFFE}));
}

// Values are typed as in a watch table (ValueFormat::parse): 1Ah, 0b101, -0x2, floats for float
// items. Read back from the simulator, so each one reached the PLC as the words expected.
void TestCli::simWriteTypedValues()
{
    // The demo ladder drives R0 in RUN; stopped, R0 keeps what is written to it.
    const Run r = runCli(
        sim({QStringLiteral("--json"),   QStringLiteral("stop"),     QStringLiteral("--then"),
             QStringLiteral("write"),    QStringLiteral("R0"),       QStringLiteral("1Ah"),
             QStringLiteral("--then"),   QStringLiteral("write"),    QStringLiteral("R1"),
             QStringLiteral("0b101"),    QStringLiteral("-0x2"),     QStringLiteral("--then"),
             QStringLiteral("write"),    QStringLiteral("R3:float"), QStringLiteral("1.5"),
             QStringLiteral("-2.5"),     QStringLiteral("--then"),   QStringLiteral("write"),
             QStringLiteral("DR20:hex"), QStringLiteral("BEEF"),     QStringLiteral("--then"),
             QStringLiteral("write"),    QStringLiteral("Y2"),       QStringLiteral("true"),
             QStringLiteral("--then"),   QStringLiteral("read"),     QStringLiteral("R0"),
             QStringLiteral("7"),        QStringLiteral("--then"),   QStringLiteral("read"),
             QStringLiteral("DR20"),     QStringLiteral("--then"),   QStringLiteral("read"),
             QStringLiteral("Y2"),       QStringLiteral("--then"),   QStringLiteral("monitor"),
             QStringLiteral("R3:float"), QStringLiteral("R5:float"), QStringLiteral("--interval"),
             QStringLiteral("50"),       QStringLiteral("--cycles"), QStringLiteral("1")}));
    RUN_OK(r);
    QCOMPARE(r.lines().size(), 10);
    QCOMPARE(r.json(1).value(QStringLiteral("written")).toArray(), ints({26}));
    QCOMPARE(r.json(2).value(QStringLiteral("written")).toArray(), ints({5, 65534}));
    // 1.5f = 0x3FC00000, -2.5f = 0xC0200000: low word first, two registers per value.
    QCOMPARE(r.json(3).value(QStringLiteral("written")).toArray(), ints({0, 0x3FC0, 0, 0xC020}));
    QCOMPARE(r.json(4).value(QStringLiteral("written")).toArray(), ints({0xBEEF}));
    QCOMPARE(r.json(5).value(QStringLiteral("written")).toArray(), ints({1}));
    QCOMPARE(r.json(6).value(QStringLiteral("values")).toArray(),
             ints({26, 5, 65534, 0, 0x3FC0, 0, 0xC020}));
    QCOMPARE(r.json(7).value(QStringLiteral("values")).toArray(), ints({0xBEEF}));
    QCOMPARE(r.json(8).value(QStringLiteral("values")).toArray(), ints({1}));
    // The monitor joins the registers back into the floats typed.
    QCOMPARE(r.json(9).value(QStringLiteral("text")).toArray(),
             (QJsonArray{QStringLiteral("1.5"), QStringLiteral("-2.5")}));
}

void TestCli::simDiscreteSetThenRead()
{
    const Run r
        = runCli(sim({QStringLiteral("--json"), QStringLiteral("set"), QStringLiteral("M7"),
                      QStringLiteral("--then"), QStringLiteral("read"), QStringLiteral("M6"),
                      QStringLiteral("3"), QStringLiteral("--then"), QStringLiteral("write"),
                      QStringLiteral("M6"), QStringLiteral("on"), QStringLiteral("off"),
                      QStringLiteral("--then"), QStringLiteral("read"), QStringLiteral("M6..M8")}));
    RUN_OK(r);
    QCOMPARE(r.json(0).value(QStringLiteral("action")).toString(), QStringLiteral("set"));
    QCOMPARE(r.json(1).value(QStringLiteral("values")).toArray(), ints({0, 1, 0}));
    QCOMPARE(r.json(3).value(QStringLiteral("values")).toArray(), ints({1, 0, 0}));
}

void TestCli::simDisableForced()
{
    const Run r
        = runCli(sim({QStringLiteral("--json"), QStringLiteral("disable"), QStringLiteral("Y5"),
                      QStringLiteral("--then"), QStringLiteral("forced"), QStringLiteral("Y4"),
                      QStringLiteral("3"), QStringLiteral("--then"), QStringLiteral("enable"),
                      QStringLiteral("Y5"), QStringLiteral("--then"), QStringLiteral("forced"),
                      QStringLiteral("Y4"), QStringLiteral("3")}));
    RUN_OK(r);
    QCOMPARE(r.json(1).value(QStringLiteral("forced")).toArray(), ints({0, 1, 0}));
    QCOMPARE(r.json(3).value(QStringLiteral("forced")).toArray(), ints({0, 0, 0}));
}

void TestCli::simLoopback()
{
    const Run r
        = runCli(sim({QStringLiteral("--json"), QStringLiteral("loopback"), QStringLiteral("HELLO"),
                      QStringLiteral("--count"), QStringLiteral("5")}));
    RUN_OK(r);
    const QJsonObject o = r.json();
    QCOMPARE(o.value(QStringLiteral("sent")).toInt(), 5);
    QCOMPARE(o.value(QStringLiteral("ok")).toInt(), 5);
    QCOMPARE(o.value(QStringLiteral("mismatches")).toInt(), 0);
    QCOMPARE(o.value(QStringLiteral("timeouts")).toInt(), 0);
    QVERIFY(o.value(QStringLiteral("minMs")).toDouble()
            <= o.value(QStringLiteral("meanMs")).toDouble());
    QVERIFY(o.value(QStringLiteral("meanMs")).toDouble()
            <= o.value(QStringLiteral("maxMs")).toDouble());
}

void TestCli::simMonitorThreeCycles()
{
    const Run r
        = runCli(sim({QStringLiteral("--json"), QStringLiteral("monitor"), QStringLiteral("R0..R1"),
                      QStringLiteral("Y0"), QStringLiteral("--interval"), QStringLiteral("100"),
                      QStringLiteral("--cycles"), QStringLiteral("3")}));
    RUN_OK(r);
    QCOMPARE(r.lines().size(), 3);
    qint64 lastScans = -1;
    for (int i = 0; i < 3; ++i) {
        const QJsonObject o = r.json(i);
        QCOMPARE(o.value(QStringLiteral("cycle")).toInt(), i + 1);
        QCOMPARE(o.value(QStringLiteral("addresses")).toArray(),
                 (QJsonArray{QStringLiteral("R0"), QStringLiteral("R1"), QStringLiteral("Y0")}));
        const QJsonArray v = o.value(QStringLiteral("values")).toArray();
        QCOMPARE(v.size(), 3);
        QVERIFY(v.at(0).isDouble());
        // The demo ladder counts scans in R0: it never goes back.
        QVERIFY(v.at(0).toInteger() >= lastScans);
        lastScans = v.at(0).toInteger();
        // ISO 8601 with the UTC offset, as the CSV log writes it (issue 32).
        const QString time = o.value(QStringLiteral("time")).toString();
        QVERIFY2(QRegularExpression(
                     QStringLiteral(R"(^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}[+-]\d\d:\d\d$)"))
                     .match(time)
                     .hasMatch(),
                 qPrintable(time));
        QVERIFY(QDateTime::fromString(time, Qt::ISODateWithMs).isValid());
    }
}

// Ctrl-C (or SIGTERM) ends a monitor cleanly: exit 0, every row shown is in the data log. Also when
// the program was started by a script without job control, where SIGINT arrives ignored.
void TestCli::simMonitorStopsOnInterrupt()
{
#ifdef Q_OS_UNIX
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("log.csv"));
    QProcess p;
    p.setChildProcessModifier([] { ::signal(SIGINT, SIG_IGN); });
    p.start(QStringLiteral(FATEK_CLI_PATH),
            sim({QStringLiteral("--csv"), QStringLiteral("monitor"), QStringLiteral("R0"),
                 QStringLiteral("--interval"), QStringLiteral("100"), QStringLiteral("--output"),
                 path}));
    QVERIFY(p.waitForStarted(10000));
    QByteArray out;
    QTRY_VERIFY_WITH_TIMEOUT((out += p.readAllStandardOutput()).count('\n') >= 4, 20000);
    ::kill(static_cast<pid_t>(p.processId()), SIGINT);
    QVERIFY2(p.waitForFinished(10000), "fatek-cli kept running after Ctrl-C");
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), 0);
    out += p.readAllStandardOutput();
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    // The file starts with the byte order mark (Excel on Windows), stdout does not (a pipe).
    QVERIFY(!out.startsWith("\xEF\xBB\xBF"));
    QCOMPARE(f.readAll(), QByteArray("\xEF\xBB\xBF") + out);
#else
    QSKIP("Unix signals");
#endif
}

void TestCli::simMonitorTable()
{
    // R50: outside what the demo ladder drives (R0, R1, DR10), so it stays 0.
    const Run r = runCli(
        sim({QStringLiteral("monitor"), QStringLiteral("R50"), QStringLiteral("--interval"),
             QStringLiteral("50"), QStringLiteral("--cycles"), QStringLiteral("3")}));
    RUN_OK(r);
    const QStringList l = r.lines();
    QCOMPARE(l.size(), 4);
    QVERIFY(l.at(0).startsWith(QLatin1String("cycle")));
    QVERIFY(l.at(0).endsWith(QLatin1String("R50")));
    QVERIFY(l.at(3).startsWith(QLatin1String("3 ")));
    QVERIFY(l.at(3).endsWith(QLatin1String(" 0")));
}

void TestCli::simRawFrame()
{
    const Run r = runCli(sim({QStringLiteral("--json"), QStringLiteral("raw"),
                              QStringLiteral("--frame"), QStringLiteral("0140")}));
    RUN_OK(r);
    const QJsonObject o = r.json();
    // STX "0140" LRC ETX: the LRC of 02 30 31 34 30 is C7.
    QCOMPARE(o.value(QStringLiteral("sent")).toString(), QStringLiteral("02 30 31 34 30 43 37 03"));
    // Station 01, command 40, error 0, STATUS1 01 (RUN).
    QVERIFY2(
        o.value(QStringLiteral("answerText")).toString().startsWith(QLatin1String("<02>0140001")),
        qPrintable(r.out));

    // Unframed bytes reach the wire as typed; an incomplete frame gets no answer: a link failure.
    const Run bare = runCli(sim({QStringLiteral("--timeout"), QStringLiteral("200"),
                                 QStringLiteral("raw"), QStringLiteral("0140")}));
    QCOMPARE(bare.code, 3);
    QVERIFY(bare.err.contains(QLatin1String("No answer")));
}

void TestCli::simJsonShape()
{
    const Run r
        = runCli(sim({QStringLiteral("--json"), QStringLiteral("write"), QStringLiteral("R12"),
                      QStringLiteral("4261"), QStringLiteral("32708"), QStringLiteral("1"),
                      QStringLiteral("--then"), QStringLiteral("read"), QStringLiteral("R12"),
                      QStringLiteral("3")}));
    RUN_OK(r);
    QCOMPARE(r.lines().at(1),
             QStringLiteral("{\"address\":\"R12\",\"station\":1,\"values\":[4261,32708,1]}"));

    const Run e
        = runCli(sim({QStringLiteral("--json"), QStringLiteral("read"), QStringLiteral("R5000")}));
    QCOMPARE(e.code, 4);
    const QJsonObject o = e.json();
    QCOMPARE(o.value(QStringLiteral("code")).toInt(), 4);
    QVERIFY(o.value(QStringLiteral("error")).toString().startsWith(QLatin1String("PLC error A")));
    QCOMPARE(o.value(QStringLiteral("plcError")).toString(), QStringLiteral("A"));
}

// Issue 57: every CSV file written starts with the UTF-8 byte order mark (Excel on Windows reads
// it as UTF-8 then), with CRLF under --crlf; CSV on stdout has neither (a pipe is not Excel); a
// data log appended to keeps its own line ends and gets no second mark.
void TestCli::simCsvFilesForExcel()
{
    QTemporaryDir dir;
    const QString log = dir.filePath(QStringLiteral("log.csv"));
    const QStringList monitor{
        QStringLiteral("--csv"),      QStringLiteral("monitor"),  QStringLiteral("R20"),
        QStringLiteral("--interval"), QStringLiteral("50"),       QStringLiteral("--cycles"),
        QStringLiteral("2"),          QStringLiteral("--output"), log};
    const Run m = runCli(sim(QStringList{QStringLiteral("--crlf")} + monitor));
    RUN_OK(m);
    QVERIFY2(m.out.startsWith(QLatin1String("timestamp,R20,status\n")), qPrintable(m.out));
    QVERIFY(!m.out.contains(QChar(0xFEFF)));
    QVERIFY(!m.out.contains(QLatin1Char('\r')));
    QByteArray data = fileBytes(log);
    QVERIFY2(data.startsWith("\xEF\xBB\xBFtimestamp,R20,status\r\n"), data.constData());
    QCOMPARE(data.count('\n'), 3);
    QCOMPARE(data.count("\r\n"), 3);
    // Appended to without --crlf: the file's own CRLF, one mark.
    const Run again = runCli(sim(monitor));
    RUN_OK(again);
    data = fileBytes(log);
    QCOMPARE(data.count('\n'), 5);
    QCOMPARE(data.count("\r\n"), 5);
    QCOMPARE(data.count("\xEF\xBB\xBF"), 1);

    // A snapshot as CSV: the mark, CRLF under --crlf, LF without.
    const QString crlf = dir.filePath(QStringLiteral("crlf.csv"));
    const Run crlfSnapshot = runCli(sim(
        {QStringLiteral("--crlf"), QStringLiteral("snapshot"), crlf, QStringLiteral("R0..R3")}));
    RUN_OK(crlfSnapshot);
    data = fileBytes(crlf);
    QVERIFY2(data.startsWith("\xEF\xBB\xBF# fatek-studio-snapshot 1\r\n"), data.constData());
    QVERIFY(data.contains("address,value,hex\r\nR0,"));
    QCOMPARE(data.count('\n'), data.count("\r\n"));
    const QString lf = dir.filePath(QStringLiteral("lf.csv"));
    const Run lfSnapshot = runCli(sim({QStringLiteral("snapshot"), lf, QStringLiteral("R0..R3")}));
    RUN_OK(lfSnapshot);
    data = fileBytes(lf);
    QVERIFY2(data.startsWith("\xEF\xBB\xBF# fatek-studio-snapshot 1\n"), data.constData());
    QVERIFY(!data.contains('\r'));
    // Both read back: the two files compared offline agree on R2..R3 (the demo ladder may move R0
    // and R1 between the two snapshots).
    const Run d = runCli({QStringLiteral("diff"), crlf, lf, QStringLiteral("R2..R3")});
    QVERIFY2(d.code == 0, qPrintable(d.err + d.out));
}

void TestCli::simCsvShape()
{
    const Run r
        = runCli(sim({QStringLiteral("--csv"), QStringLiteral("write"), QStringLiteral("R12"),
                      QStringLiteral("7"), QStringLiteral("8"), QStringLiteral("--then"),
                      QStringLiteral("read"), QStringLiteral("R12"), QStringLiteral("2")}));
    RUN_OK(r);
    const QStringList l = r.lines();
    QCOMPARE(l.size(), 6);
    QCOMPARE(l.at(0), QStringLiteral("station,address,written"));
    QCOMPARE(l.at(3), QStringLiteral("station,address,value"));
    QCOMPARE(l.at(4), QStringLiteral("1,R12,7"));
    QCOMPARE(l.at(5), QStringLiteral("1,R13,8"));

    const Run m
        = runCli(sim({QStringLiteral("--csv"), QStringLiteral("monitor"), QStringLiteral("R20"),
                      QStringLiteral("Y1"), QStringLiteral("--interval"), QStringLiteral("50"),
                      QStringLiteral("--cycles"), QStringLiteral("2")}));
    RUN_OK(m);
    QCOMPARE(m.lines().size(), 3);
    // The data log format (docs/trends.md): timestamp, one column per item, status.
    QCOMPARE(m.lines().at(0), QStringLiteral("timestamp,R20,Y1,status"));
    QVERIFY(m.lines().at(2).endsWith(QLatin1String(",0,0,ok")));

    // R20 as a number and as hex: the same header as the GUI's log, each column names its format.
    const Run two
        = runCli(sim({QStringLiteral("--csv"), QStringLiteral("monitor"), QStringLiteral("R20"),
                      QStringLiteral("R20:hex"), QStringLiteral("--interval"), QStringLiteral("50"),
                      QStringLiteral("--cycles"), QStringLiteral("1")}));
    RUN_OK(two);
    QCOMPARE(two.lines().size(), 2);
    QCOMPARE(two.lines().at(0), QStringLiteral("timestamp,R20 [signed],R20 [hex],status"));
    QVERIFY(two.lines().at(1).endsWith(QLatin1String(",0,0x0000,ok")));
}

// --names: the ladder project's comment/symbol list names the columns, as in the GUI.
void TestCli::simMonitorNames()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString names = dir.filePath(QStringLiteral("names.txt"));
    {
        QFile f(names);
        QVERIFY(f.open(QIODevice::WriteOnly));
        // Tab-separated, a Big5 name (\xB2\x47\xA6\xEC is "液位"), one bad line.
        f.write("R00020\t\xB2\x47\xA6\xEC\tcm\nQ1\tNothing\nY1\tPump\n");
    }
    const Run m
        = runCli(sim({QStringLiteral("--csv"), QStringLiteral("monitor"), QStringLiteral("R20"),
                      QStringLiteral("Y1"), QStringLiteral("R21"), QStringLiteral("--cycles"),
                      QStringLiteral("1"), QStringLiteral("--names"), names}));
    RUN_OK(m);
    QCOMPARE(m.lines().size(), 2);
    QCOMPARE(m.lines().at(0), QString::fromUtf8("timestamp,液位 (R20),Pump (Y1),R21,status"));
    QVERIFY2(m.err.contains(QLatin1String("Names imported: 2, lines skipped: 1 (line 2: ")),
             qPrintable(m.err));

    const Run table
        = runCli(sim({QStringLiteral("monitor"), QStringLiteral("Y1"), QStringLiteral("--cycles"),
                      QStringLiteral("1"), QStringLiteral("--names"), names}));
    RUN_OK(table);
    QVERIFY2(table.out.contains(QLatin1String("Pump (Y1)")), qPrintable(table.out));

    const Run missing = runCli(
        sim({QStringLiteral("monitor"), QStringLiteral("Y1"), QStringLiteral("--cycles"),
             QStringLiteral("1"), QStringLiteral("--names"), dir.filePath(QStringLiteral("no"))}));
    QCOMPARE(missing.code, 2);
    QVERIFY2(missing.err.contains(QLatin1String("Cannot read ")), qPrintable(missing.err));
}

void TestCli::simMixedRead()
{
    const Run r
        = runCli(sim({QStringLiteral("--json"), QStringLiteral("write"), QStringLiteral("R30"),
                      QStringLiteral("99"), QStringLiteral("--then"), QStringLiteral("set"),
                      QStringLiteral("M3"), QStringLiteral("--then"), QStringLiteral("read"),
                      QStringLiteral("R30"), QStringLiteral("M3"), QStringLiteral("M4")}));
    RUN_OK(r);
    QCOMPARE(r.lines().size(), 5);
    QCOMPARE(r.json(2).value(QStringLiteral("address")).toString(), QStringLiteral("R30"));
    QCOMPARE(r.json(2).value(QStringLiteral("values")).toArray(), ints({99}));
    QCOMPARE(r.json(3).value(QStringLiteral("values")).toArray(), ints({1}));
    QCOMPARE(r.json(4).value(QStringLiteral("values")).toArray(), ints({0}));
}

// Issue 32: the bash completion, made by the program from its command table, completes what a
// person types: commands, options, formats, the named links of links.conf, commands after --then,
// files after backup. (zsh's script is checked for syntax where zsh is installed.)
void TestCli::completions()
{
#ifndef Q_OS_UNIX
    QSKIP("bash and zsh completions are for Unix shells");
#else
    const QString bash = QStandardPaths::findExecutable(QStringLiteral("bash"));
    QVERIFY(!bash.isEmpty());
    QTemporaryDir dir;
    const Run script = runCli({QStringLiteral("--completion"), QStringLiteral("bash")});
    RUN_OK(script);
    QFile file(dir.filePath(QStringLiteral("fatek-cli.bash")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(script.out.toUtf8());
    file.close();
    QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("config/fatek-studio")));
    QFile links(dir.filePath(QStringLiteral("config/fatek-studio/links.conf")));
    QVERIFY(links.open(QIODevice::WriteOnly));
    links.write("# bench\nline1 = tcp://10.0.0.5\npress=serial://COM3  # east\n");
    links.close();
    // What the shell offers for the words typed so far (the last one being completed), given as
    // bash gives them: the line up to the cursor (tests/docs/check_cli_completion.py presses TAB
    // in a real interactive bash).
    auto offers = [&](const QStringList &words) {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
        env.remove(QStringLiteral("FATEK_LINKS"));
        p.setProcessEnvironment(env);
        p.setWorkingDirectory(dir.path());
        p.start(bash, {QStringLiteral("-c"),
                       QStringLiteral("source fatek-cli.bash; COMP_LINE='fatek-cli %1'; "
                                      "COMP_POINT=${#COMP_LINE}; _fatek_cli; "
                                      "printf '%s\\n' \"${COMPREPLY[@]}\"")
                           .arg(words.join(QLatin1Char(' ')))});
        p.waitForFinished(10000);
        return QString::fromUtf8(p.readAllStandardOutput())
            .split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    };
    QCOMPARE(offers({QStringLiteral("re")}),
             (QStringList{QStringLiteral("read"), QStringLiteral("reset"),
                          QStringLiteral("restore"), QStringLiteral("restore-values")}));
    QCOMPARE(offers({QStringLiteral("--link"), QStringLiteral("@")}),
             (QStringList{QStringLiteral("@line1"), QStringLiteral("@press")}));
    QVERIFY(offers({QStringLiteral("--format"), QString()}).contains(QStringLiteral("ascii")));
    QCOMPARE(offers({QStringLiteral("--protocol"), QStringLiteral("b")}),
             QStringList{QStringLiteral("binary")});
    QCOMPARE(offers({QStringLiteral("--js")}), QStringList{QStringLiteral("--json")});
    QVERIFY(offers({QStringLiteral("--th")}).contains(QStringLiteral("--then")));
    // After --then a new command; after a command's own words nothing but its files.
    QVERIFY(offers({QStringLiteral("--sim"), QStringLiteral("status"), QStringLiteral("--then"),
                    QStringLiteral("mon")})
            == QStringList{QStringLiteral("monitor")});
    QCOMPARE(offers({QStringLiteral("--tcp"), QStringLiteral("plc1"), QStringLiteral("backup"),
                     QStringLiteral("fatek-cli.b")}),
             QStringList{QStringLiteral("fatek-cli.bash")});

    const QString zsh = QStandardPaths::findExecutable(QStringLiteral("zsh"));
    if (!zsh.isEmpty()) {
        const Run z = runCli({QStringLiteral("--completion"), QStringLiteral("zsh")});
        RUN_OK(z);
        QProcess p;
        p.start(zsh, {QStringLiteral("-n")});
        p.write(z.out.toUtf8());
        p.closeWriteChannel();
        QVERIFY(p.waitForFinished(10000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
    }
    const Run bad = runCli({QStringLiteral("--completion"), QStringLiteral("fish")});
    QCOMPARE(bad.code, 2);
#endif
}

// Issue 32: read takes what monitor and write take: a range longer than one request carries
// (R0..R99: two requests) and ADDR:FORMAT.
void TestCli::simReadSplitsAndFormats()
{
    const Run r = runCli(sim(
        {QStringLiteral("--json"),     QStringLiteral("write"),      QStringLiteral("R63"),
         QStringLiteral("7"),          QStringLiteral("9"),          QStringLiteral("--then"),
         QStringLiteral("write"),      QStringLiteral("R200:float"), QStringLiteral("-2.25"),
         QStringLiteral("--then"),     QStringLiteral("read"),       QStringLiteral("R0..R99"),
         QStringLiteral("--then"),     QStringLiteral("read"),       QStringLiteral("R200:float"),
         QStringLiteral("R63:hex"),    QStringLiteral("--then"),     QStringLiteral("read"),
         QStringLiteral("R200:float"), QStringLiteral("2")}));
    RUN_OK(r);
    QCOMPARE(r.lines().size(), 7);
    const QJsonArray all = r.json(2).value(QStringLiteral("values")).toArray();
    QCOMPARE(all.size(), 100);
    QCOMPARE(all.at(63).toInt(), 7); // the last element of the first request
    QCOMPARE(all.at(64).toInt(), 9); // the first of the second
    QCOMPARE(r.json(3).value(QStringLiteral("format")).toString(), QStringLiteral("float"));
    QCOMPARE(r.json(3).value(QStringLiteral("value")).toString(), QStringLiteral("-2.25"));
    QCOMPARE(r.json(3).value(QStringLiteral("words")).toArray().size(), 2);
    QCOMPARE(r.json(4).value(QStringLiteral("address")).toString(), QStringLiteral("R63"));
    QCOMPARE(r.json(4).value(QStringLiteral("value")).toString(), QStringLiteral("0x0007"));
    // A COUNT after ADDR:FORMAT counts items: R200 and R202.
    QCOMPARE(r.json(5).value(QStringLiteral("value")).toString(), QStringLiteral("-2.25"));
    QCOMPARE(r.json(6).value(QStringLiteral("address")).toString(), QStringLiteral("R202"));

    const Run bad = runCli(sim({QStringLiteral("read"), QStringLiteral("R0:bogus")}));
    QCOMPARE(bad.code, 2);
    QVERIFY2(bad.err.contains(QLatin1String("Unknown format \"bogus\" in R0:bogus")),
             qPrintable(bad.err));
}

void TestCli::plcErrorExit4()
{
    // R70000 exists on no model: refused before sending (usage). R5000 exists on the largest model
    // but not on the FBs profile: the simulator answers error A.
    const Run before = runCli(sim({QStringLiteral("read"), QStringLiteral("R70000")}));
    QCOMPARE(before.code, 2);
    QVERIFY(before.err.contains(QLatin1String("R70000")));

    const Run r = runCli(sim({QStringLiteral("read"), QStringLiteral("R5000")}));
    QCOMPARE(r.code, 4);
    QVERIFY2(r.err.contains(QLatin1String("PLC error A: illegal address R5000")),
             qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
}

void TestCli::linkFailureExit3()
{
    const Run r = runCli(
        {QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:1"), QStringLiteral("status")});
    QCOMPARE(r.code, 3);
    QVERIFY2(r.err.contains(QLatin1String("No connection")), qPrintable(r.err));
}

void TestCli::readOnlyExit5()
{
    const Run w = runCli(sim({QStringLiteral("--read-only"), QStringLiteral("write"),
                              QStringLiteral("R100"), QStringLiteral("5")}));
    QCOMPARE(w.code, 5);
    QVERIFY(!w.err.isEmpty());
    const Run s
        = runCli(sim({QStringLiteral("--read-only"), QStringLiteral("set"), QStringLiteral("Y0")}));
    QCOMPARE(s.code, 5);
    // Reading stays allowed in operator mode.
    const Run r = runCli(sim({QStringLiteral("--read-only"), QStringLiteral("--json"),
                              QStringLiteral("read"), QStringLiteral("R100")}));
    RUN_OK(r);
    QCOMPARE(r.json().value(QStringLiteral("values")).toArray(), ints({0}));
}

// What a fatek-cli run put on a loopback TCP listener: the kernel accepts and buffers while the
// test waits for the process, so everything sent is read afterwards.
static QByteArray bytesReceivedBy(QTcpServer &server)
{
    QByteArray received;
    while (server.waitForNewConnection(200)) {
        while (QTcpSocket *peer = server.nextPendingConnection()) {
            while (peer->waitForReadyRead(200))
                received += peer->readAll();
            received += peer->readAll();
            delete peer;
        }
    }
    return received;
}

// A broadcast has no station to detect the protocol with: under auto it is refused as a usage
// error and nothing reaches the wire; with --protocol it goes out.
void TestCli::broadcastUnderAutoExit2()
{
    QTcpServer listener;
    QVERIFY(listener.listen(QHostAddress::LocalHost, 0));
    const QString where = QStringLiteral("127.0.0.1:%1").arg(listener.serverPort());
    const QStringList write{QStringLiteral("--station"), QStringLiteral("0"),
                            QStringLiteral("write"), QStringLiteral("R6"), QStringLiteral("4321")};

    const Run r = runCli(QStringList{QStringLiteral("--tcp"), where} + write);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(QLatin1String("give --protocol for a broadcast")), qPrintable(r.err));
    QCOMPARE(bytesReceivedBy(listener), QByteArray());

    const Run facon = runCli(QStringList{QStringLiteral("--tcp"), where,
                                         QStringLiteral("--protocol"), QStringLiteral("facon")}
                             + write);
    RUN_OK(facon);
    // STX, station 00, command 47 (write registers): the broadcast, with no probe in front.
    const QByteArray sent = bytesReceivedBy(listener);
    QVERIFY2(sent.startsWith("\x02"
                             "0047"),
             sent.constData());
}

void TestCli::reference_data()
{
    QTest::addColumn<QString>("medium");
    QTest::addColumn<QString>("protocol");
    QTest::addColumn<int>(
        "base"); // element numbers of this row: the reference PLC is shared by all rows
    QTest::newRow("tcp facon") << QStringLiteral("tcp") << QStringLiteral("facon") << 1000;
    QTest::newRow("tcp binary") << QStringLiteral("tcp") << QStringLiteral("binary") << 1100;
    QTest::newRow("udp facon") << QStringLiteral("udp") << QStringLiteral("facon") << 1200;
    QTest::newRow("udp binary") << QStringLiteral("udp") << QStringLiteral("binary") << 1300;
}

void TestCli::reference()
{
    if (!m_refProblem.isEmpty())
        QSKIP(qPrintable(m_refProblem));
    QFETCH(QString, medium);
    QFETCH(QString, protocol);
    QFETCH(int, base);
    const QStringList link = ref(medium, protocol);
    auto cli = [&](const QStringList &args) {
        return runCli(link + args);
    };
    const QString R = QStringLiteral("R%1").arg(base);
    const QString R1 = QStringLiteral("R%1").arg(base + 1);
    const QString DR = QStringLiteral("DR%1").arg(base + 10);
    const QString Y
        = QStringLiteral("Y%1").arg(base / 10); // Y100.. are discretes far from other rows
    const QString M = QStringLiteral("M%1").arg(base);

    // run / stop, checked through STATUS1.
    Run r = cli({QStringLiteral("run"), QStringLiteral("--then"), QStringLiteral("status")});
    RUN_OK(r);
    QCOMPARE(r.json(0).value(QStringLiteral("ok")).toBool(), true);
    QCOMPARE(r.json(1).value(QStringLiteral("running")).toBool(), true);
    QCOMPARE(r.json(1).value(QStringLiteral("status1")).toInt() & 1, 1);
    QCOMPARE(r.json(1).value(QStringLiteral("protocol")).toString(),
             protocol == QLatin1String("facon") ? QStringLiteral("FACON")
                                                : QStringLiteral("binary"));
    // The reference's 53 answer follows the FACON seed layout.
    QCOMPARE(r.json(1)
                 .value(QStringLiteral("detail"))
                 .toObject()
                 .value(QStringLiteral("osVersion"))
                 .toString(),
             QStringLiteral("V3.1"));
    r = cli({QStringLiteral("stop"), QStringLiteral("--then"), QStringLiteral("status")});
    RUN_OK(r);
    QCOMPARE(r.json(1).value(QStringLiteral("running")).toBool(), false);

    // Registers: consecutive write (47) and read back (46), 16 and 32 bit, negative and hex.
    r = cli({QStringLiteral("write"), R, QStringLiteral("4261"), QStringLiteral("-1"),
             QStringLiteral("0x7FC4")});
    RUN_OK(r);
    r = cli({QStringLiteral("read"), R, QStringLiteral("3")});
    RUN_OK(r);
    QCOMPARE(r.json().value(QStringLiteral("values")).toArray(), ints({4261, 65535, 32708}));
    r = cli({QStringLiteral("write"), DR, QStringLiteral("0x12345678"), QStringLiteral("--then"),
             QStringLiteral("read"), DR, QStringLiteral("--then"), QStringLiteral("read"),
             QStringLiteral("R%1").arg(base + 10), QStringLiteral("2")});
    RUN_OK(r);
    QCOMPARE(r.json(1).value(QStringLiteral("values")).toArray(), ints({0x12345678}));
    QCOMPARE(r.json(2).value(QStringLiteral("values")).toArray(), ints({0x5678, 0x1234}));

    // Discretes: consecutive write (45) and read back (44).
    r = cli({QStringLiteral("write"), Y, QStringLiteral("1"), QStringLiteral("off"),
             QStringLiteral("on"), QStringLiteral("--then"), QStringLiteral("read"), Y,
             QStringLiteral("3")});
    RUN_OK(r);
    QCOMPARE(r.json(1).value(QStringLiteral("values")).toArray(), ints({1, 0, 1}));

    // Discrete control (42) and forced flags (43).
    r = cli({QStringLiteral("set"), M, QStringLiteral("--then"), QStringLiteral("read"), M});
    RUN_OK(r);
    QCOMPARE(r.json(1).value(QStringLiteral("values")).toArray(), ints({1}));
    r = cli({QStringLiteral("reset"), M, QStringLiteral("--then"), QStringLiteral("read"), M});
    RUN_OK(r);
    QCOMPARE(r.json(1).value(QStringLiteral("values")).toArray(), ints({0}));
    r = cli({QStringLiteral("disable"), M, QStringLiteral("--then"), QStringLiteral("forced"), M,
             QStringLiteral("2")});
    RUN_OK(r);
    QCOMPARE(r.json(1).value(QStringLiteral("forced")).toArray(), ints({1, 0}));
    r = cli({QStringLiteral("enable"), M, QStringLiteral("--then"), QStringLiteral("forced"), M,
             QStringLiteral("2")});
    RUN_OK(r);
    QCOMPARE(r.json(1).value(QStringLiteral("forced")).toArray(), ints({0, 0}));

    // Mixed read (48).
    r = cli({QStringLiteral("read"), R, DR, Y});
    RUN_OK(r);
    QCOMPARE(r.lines().size(), 3);
    QCOMPARE(r.json(0).value(QStringLiteral("values")).toArray(), ints({4261}));
    QCOMPARE(r.json(1).value(QStringLiteral("values")).toArray(), ints({0x12345678}));
    QCOMPARE(r.json(2).value(QStringLiteral("values")).toArray(), ints({1}));

    // Loopback (4E).
    r = cli({QStringLiteral("loopback"), QStringLiteral("ABC123"), QStringLiteral("--count"),
             QStringLiteral("3")});
    RUN_OK(r);
    QCOMPARE(r.json().value(QStringLiteral("ok")).toInt(), 3);
    QCOMPARE(r.json().value(QStringLiteral("mismatches")).toInt(), 0);

    // Monitor through the session's planned polling.
    r = cli({QStringLiteral("monitor"), QStringLiteral("%1..%2").arg(R, R1), DR,
             QStringLiteral("--interval"), QStringLiteral("50"), QStringLiteral("--cycles"),
             QStringLiteral("2")});
    RUN_OK(r);
    QCOMPARE(r.lines().size(), 2);
    QCOMPARE(r.json(1).value(QStringLiteral("values")).toArray(), ints({4261, 65535, 0x12345678}));

    // Raw frame with framing added by the session: brief status of station 1 in STOP.
    if (protocol == QLatin1String("facon")) {
        r = cli({QStringLiteral("raw"), QStringLiteral("--frame"), QStringLiteral("0140")});
        RUN_OK(r);
        QVERIFY2(r.json()
                     .value(QStringLiteral("answerText"))
                     .toString()
                     .startsWith(QLatin1String("<02>0140000")),
                 qPrintable(r.out));
    } else {
        r = cli({QStringLiteral("raw"), QStringLiteral("--frame"), QStringLiteral("01 40")});
        RUN_OK(r);
        // Answer header 52, then station 01, command 40, error 00, STATUS1 00 (STOP).
        const QString answer = r.json().value(QStringLiteral("answer")).toString();
        QVERIFY2(answer.startsWith(QLatin1String("52 ")), qPrintable(answer));
        QVERIFY2(answer.contains(QLatin1String(" 01 40 00 00")), qPrintable(answer));
    }

    // The reference has the largest model's ranges: a span past them is refused before sending.
    r = cli({QStringLiteral("read"), QStringLiteral("R65535"), QStringLiteral("2")});
    QCOMPARE(r.code, 2);

    // Station scan (40 per station): only station 1 answers.
    r = cli({QStringLiteral("scan"), QStringLiteral("1..2")});
    RUN_OK(r);
    QCOMPARE(r.lines().size(), 1);
    QCOMPARE(r.json().value(QStringLiteral("station")).toInt(), 1);
}

void TestCli::referenceAutoDetect()
{
    if (!m_refProblem.isEmpty())
        QSKIP(qPrintable(m_refProblem));
    // Default protocol for a real link: auto-detect (FACON answers first on the reference).
    const Run r = runCli({QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:%1").arg(m_refTcp),
                          QStringLiteral("--json"), QStringLiteral("status")});
    RUN_OK(r);
    QCOMPARE(r.json().value(QStringLiteral("protocol")).toString(), QStringLiteral("FACON"));
}

void TestCli::referenceReadOnlyKeepsValue()
{
    if (!m_refProblem.isEmpty())
        QSKIP(qPrintable(m_refProblem));
    const QStringList link = ref(QStringLiteral("tcp"), QStringLiteral("facon"));
    Run r = runCli(
        link + QStringList{QStringLiteral("write"), QStringLiteral("R2000"), QStringLiteral("11")});
    RUN_OK(r);
    r = runCli(link
               + QStringList{QStringLiteral("--read-only"), QStringLiteral("write"),
                             QStringLiteral("R2000"), QStringLiteral("99")});
    QCOMPARE(r.code, 5);
    QCOMPARE(r.json().value(QStringLiteral("code")).toInt(), 5);
    r = runCli(link + QStringList{QStringLiteral("read"), QStringLiteral("R2000")});
    RUN_OK(r);
    QCOMPARE(r.json().value(QStringLiteral("values")).toArray(), ints({11}));
}

// The typed forms against the independent reference PLC: what it holds is what was meant.
void TestCli::referenceWriteTypedValues()
{
    if (!m_refProblem.isEmpty())
        QSKIP(qPrintable(m_refProblem));
    const QStringList link = ref(QStringLiteral("tcp"), QStringLiteral("facon"));
    Run r = runCli(link
                   + QStringList{QStringLiteral("write"), QStringLiteral("R2100"),
                                 QStringLiteral("1Ah"), QStringLiteral("0b1010"),
                                 QStringLiteral("--then"), QStringLiteral("write"),
                                 QStringLiteral("R2102:float"), QStringLiteral("-2.5")});
    RUN_OK(r);
    r = runCli(link
               + QStringList{QStringLiteral("read"), QStringLiteral("R2100"), QStringLiteral("4")});
    RUN_OK(r);
    QCOMPARE(r.json().value(QStringLiteral("values")).toArray(), ints({26, 10, 0, 0xC020}));
}

void TestCli::referenceMonitorCsvLog()
{
    if (!m_refProblem.isEmpty())
        QSKIP(qPrintable(m_refProblem));
    const QStringList link{QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:%1").arg(m_refTcp),
                           QStringLiteral("--protocol"), QStringLiteral("facon")};
    // 1.5f = 0x3FC00000: R400 low word 0x0000, R401 high word 0x3FC0; R402 = -5; R403 = 0x1A.
    const Run w = runCli(link
                         + QStringList{QStringLiteral("write"), QStringLiteral("R400"),
                                       QStringLiteral("0"), QStringLiteral("0x3FC0"),
                                       QStringLiteral("-5"), QStringLiteral("0x1A")});
    RUN_OK(w);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("log.csv"));
    const QStringList monitor
        = link + QStringList{QStringLiteral("--csv"),      QStringLiteral("monitor"),
                             QStringLiteral("R400:float"), QStringLiteral("R402"),
                             QStringLiteral("R403:hex"),   QStringLiteral("R402:unsigned"),
                             QStringLiteral("--interval"), QStringLiteral("50"),
                             QStringLiteral("--cycles"),   QStringLiteral("4"),
                             QStringLiteral("--output"),   path};
    const Run r = runCli(monitor);
    RUN_OK(r);
    const QStringList l = r.lines();
    QCOMPARE(l.size(), 5);
    // R402 twice, in two formats: each column says which (docs/trends.md).
    QCOMPARE(l.at(0), QStringLiteral("timestamp,R400,R402 [signed],R403,R402 [unsigned],status"));
    QDateTime previous;
    for (int i = 1; i < 5; ++i) {
        const QStringList cells = l.at(i).split(QLatin1Char(','));
        QCOMPARE(cells.size(), 6);
        const QDateTime t = QDateTime::fromString(cells.at(0), Qt::ISODateWithMs);
        QVERIFY2(t.isValid(), qPrintable(cells.at(0)));
        // Milliseconds and the UTC offset are in the text.
        QVERIFY2(QRegularExpression(QStringLiteral("\\.\\d{3}[+-]\\d\\d:\\d\\d$"))
                     .match(cells.at(0))
                     .hasMatch(),
                 qPrintable(cells.at(0)));
        if (previous.isValid())
            QVERIFY2(t > previous, qPrintable(l.join(QLatin1Char('\n'))));
        previous = t;
        QCOMPARE(cells.mid(1),
                 (QStringList{QStringLiteral("1.5"), QStringLiteral("-5"), QStringLiteral("0x001A"),
                              QStringLiteral("65531"), QStringLiteral("ok")}));
    }
    // The log file holds the same rows; a second run appends without a second header.
    const Run again = runCli(monitor);
    RUN_OK(again);
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QStringList logged
        = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(logged.size(), 9);
    QCOMPARE(logged.mid(0, 5), l);
    QCOMPARE(logged.count(l.at(0)), 1);

    // Another column layout into the same file is refused (usage), the file stays as it was.
    const Run other = runCli(link
                             + QStringList{QStringLiteral("monitor"), QStringLiteral("R400"),
                                           QStringLiteral("--cycles"), QStringLiteral("1"),
                                           QStringLiteral("--output"), path});
    QCOMPARE(other.code, 2);
    QVERIFY2(other.err.contains(QLatin1String("other columns")), qPrintable(other.err));
    QCOMPARE(QFileInfo(path).size(), f.size());
    // A bad format name is a usage error naming the choices.
    const Run bad
        = runCli(link + QStringList{QStringLiteral("monitor"), QStringLiteral("R0:hexx")});
    QCOMPARE(bad.code, 2);
    QVERIFY(bad.err.contains(QLatin1String("float")));
}

void TestCli::filesOnFullDevice_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("name"); // a link to /dev/full, named as the command wants
    // After the file: a snapshot of a few ranges (what is written does not matter here; the
    // whole PLC took more than the 30 s a run may take under ThreadSanitizer on a busy machine).
    QTest::addColumn<QStringList>("after");
    QTest::newRow("backup") << QStringList{QStringLiteral("backup")} << QString() << QStringList();
    QTest::newRow("backup via link")
        << QStringList{QStringLiteral("backup")} << QStringLiteral("b.fprog") << QStringList();
    QTest::newRow("snapshot json")
        << QStringList{QStringLiteral("snapshot")} << QStringLiteral("s.json")
        << QStringList{QStringLiteral("R0..R99, X0..X255")};
    QTest::newRow("snapshot csv") << QStringList{QStringLiteral("snapshot")}
                                  << QStringLiteral("s.csv")
                                  << QStringList{QStringLiteral("R0..R99, X0..X255")};
}

// The report: "backup /dev/full" ended with 0. Now exit 1 with the system's reason, and /dev/full
// (also reached through a link) is written as the device it is, never replaced by a file.
void TestCli::filesOnFullDevice()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, name);
    QFETCH(QStringList, after);
    if (!isCharacterDevice(fullDevice))
        QSKIP("/dev/full is not a character device here");
    QTemporaryDir dir;
    QString path = fullDevice;
    if (!name.isEmpty()) {
        path = dir.filePath(name);
        QVERIFY(QFile::link(fullDevice, path));
    }
    const QStringList before
        = QDir(QStringLiteral("/dev")).entryList({QStringLiteral("full*")}, QDir::System);
    const Run r = runCli(sim(arguments + QStringList{path} + after));
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(noSpace), qPrintable(r.err));
    QVERIFY2(onlyOwnLines(r.err), qPrintable(r.err));
    QVERIFY(isCharacterDevice(fullDevice));
    QCOMPARE(QDir(QStringLiteral("/dev")).entryList({QStringLiteral("full*")}, QDir::System),
             before);
    if (!name.isEmpty())
        QVERIFY(QFileInfo(path).isSymLink());
}

void TestCli::filesOnFullDisk_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("name");
    QTest::newRow("backup") << QStringLiteral("backup") << QStringLiteral("b.fprog");
    QTest::newRow("snapshot json") << QStringLiteral("snapshot") << QStringLiteral("s.json");
    QTest::newRow("snapshot csv") << QStringLiteral("snapshot") << QStringLiteral("s.csv");
}

// The report: a backup onto a disk with 24 KB free ended with 0 and a CRC, the file cut short.
// Now exit 1 with the reason, and the backup that was there before is as it was.
void TestCli::filesOnFullDisk()
{
    QFETCH(QString, command);
    QFETCH(QString, name);
    QTemporaryDir dir;
    const QString disk = dir.filePath(QStringLiteral("small"));
    TestUtil::TmpfsMount mount; // 64 KiB, the report's setup
    if (const QString problem = mount.mount(disk, 64); !problem.isEmpty())
        QSKIP(qPrintable(problem));
    QVERIFY(writeFile(QDir(disk).filePath(QStringLiteral("f")), QByteArray(40000, '\0')));
    const QString path = QDir(disk).filePath(name);
    const QByteArray old = "the backup of yesterday\n";
    QVERIFY(writeFile(path, old));
    const QStringList files = QDir(disk).entryList(QDir::Files);
    // The snapshot of every element of the model (about 470 KB) does not fit either.
    const Run r = runCli(sim({command, path}));
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(noSpace), qPrintable(r.err));
    QCOMPARE(fileBytes(path), old);
    QCOMPARE(QDir(disk).entryList(QDir::Files), files);
}

// monitor --output /dev/full: exit 1 at once with the reason, no Qt warning on stderr.
void TestCli::monitorLogOnFullDevice()
{
    if (!isCharacterDevice(fullDevice))
        QSKIP("/dev/full is not a character device here");
    const Run r
        = runCli(sim({QStringLiteral("monitor"), QStringLiteral("R0"), QStringLiteral("--interval"),
                      QStringLiteral("100"), QStringLiteral("--output"), fullDevice}),
                 10000);
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(noSpace) && r.err.contains(fullDevice), qPrintable(r.err));
    QVERIFY2(onlyOwnLines(r.err), qPrintable(r.err));
    QVERIFY(isCharacterDevice(fullDevice));
}

// A data log that fills the disk half way: said at once (once), the monitor goes on polling to its
// last cycle, and ends with exit 1 (the file was not written whole).
void TestCli::monitorLogFillsTheDisk()
{
    QTemporaryDir dir;
    const QString disk = dir.filePath(QStringLiteral("small"));
    TestUtil::TmpfsMount mount; // 64 KiB, the report's setup
    if (const QString problem = mount.mount(disk, 64); !problem.isEmpty())
        QSKIP(qPrintable(problem));
    // One page left: the header and a few rows of 100 elements (about 530 bytes each) fit, then
    // the disk is full.
    QVERIFY(writeFile(QDir(disk).filePath(QStringLiteral("f")), QByteArray(61440, '\0')));
    const QString path = QDir(disk).filePath(QStringLiteral("log.csv"));
    const Run r = runCli(
        sim({QStringLiteral("--json"), QStringLiteral("monitor"), QStringLiteral("R0..R99:hex"),
             QStringLiteral("--interval"), QStringLiteral("100"), QStringLiteral("--cycles"),
             QStringLiteral("20"), QStringLiteral("--output"), path}));
    QCOMPARE(r.code, 1);
    QCOMPARE(r.err.count(noSpace), 1);
    QVERIFY2(onlyOwnLines(r.err), qPrintable(r.err));
    // Every cycle was shown, also those after the log stopped (the last line: the error object).
    QStringList cycles = r.lines();
    cycles.removeIf([](const QString &l) { return !l.contains(QLatin1String("\"cycle\"")); });
    QCOMPARE(cycles.size(), 20);
    QVERIFY(fileBytes(path).startsWith("\xEF\xBB\xBFtimestamp,R0,R1,"));
}

void TestCli::outputOnFullDevice_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("read") << sim({QStringLiteral("read"), QStringLiteral("R0")});
    QTest::newRow("read --json") << sim(
        {QStringLiteral("--json"), QStringLiteral("read"), QStringLiteral("R0")});
    QTest::newRow("monitor") << sim({QStringLiteral("monitor"), QStringLiteral("R0"),
                                     QStringLiteral("--interval"), QStringLiteral("100")});
    QTest::newRow("--help") << QStringList{QStringLiteral("--help")};
}

// The report: "read R0 > /dev/full" ended with 0. Output that cannot be written is exit 1 with the
// reason on stderr; a monitor (which would run for ever) ends at once.
void TestCli::outputOnFullDevice()
{
    QFETCH(QStringList, arguments);
    if (!isCharacterDevice(fullDevice))
        QSKIP("/dev/full is not a character device here");
    const Run r = runCliInto(fullDevice, arguments);
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(QStringLiteral("Cannot write the output: ") + noSpace),
             qPrintable(r.err));
    QVERIFY2(onlyOwnLines(r.err), qPrintable(r.err));
    QVERIFY(isCharacterDevice(fullDevice));
}

// The report: "monitor R0 | head -2" never returned. The reader (head, as in the report) reads
// two lines and closes its end of the pipe: the monitor ends within a few seconds, quietly, with
// 141 (as if by SIGPIPE). (QProcess::closeReadChannel only stops reading, it keeps the pipe open.)
void TestCli::outputIntoClosedPipe()
{
    const QString headProgram = QStandardPaths::findExecutable(QStringLiteral("head"));
    if (headProgram.isEmpty())
        QSKIP("head not found on PATH");
    QProcess p;
    QProcess head;
    p.setStandardOutputProcess(&head);
    head.start(headProgram, {QStringLiteral("-n"), QStringLiteral("2")});
    p.start(QStringLiteral(FATEK_CLI_PATH),
            sim({QStringLiteral("monitor"), QStringLiteral("R0"), QStringLiteral("--interval"),
                 QStringLiteral("100")}));
    QVERIFY(head.waitForStarted(10000));
    QVERIFY(p.waitForStarted(10000));
    QVERIFY2(head.waitForFinished(20000), "head did not get two lines");
    QCOMPARE(head.readAllStandardOutput().count('\n'), 2);
    const bool ended = p.waitForFinished(5000);
    if (!ended) {
        p.kill();
        p.waitForFinished();
    }
    QVERIFY2(ended, "fatek-cli kept running with nobody reading its output");
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), 141);
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QVERIFY2(!err.contains(QLatin1String("Cannot write")), qPrintable(err));
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
