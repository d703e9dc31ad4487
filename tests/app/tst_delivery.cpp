// Nothing written is lost: many short-lived fatek-cli processes write to a simulated PLC over TCP
// and over a socat pty pair, and every frame must be on the simulator's count. Also the raw
// command under protocol auto-detect (no probe for a frame that needs none, the right station,
// binary framing for hex bytes).
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"

#include <QEventLoop>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>

#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <csignal>

#ifdef Q_OS_UNIX
#include <fcntl.h>
#include <unistd.h>
#endif

#include <memory>

using namespace Fatek;

namespace {

using Run = TestUtil::ProgramRun;

// Runs fatek-cli with the event loop turning, so that the in-process simulator answers.
Run runCli(const QStringList &arguments, int timeoutMs = 30000)
{
    return TestUtil::runProgram(QStringLiteral(FATEK_CLI_PATH), arguments, timeoutMs);
}

using TestUtil::startPtyPair;

} // namespace

#define RUN_OK(r)                                                                                  \
    QVERIFY2((r).code == 0,                                                                        \
             qPrintable(QStringLiteral("exit %1: %2 %3").arg((r).code).arg((r).err, (r).out)))

class TestDelivery : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void writesReachThePlc_data();
    void writesReachThePlc();
    void rawUnframedUnderAutoNeedsNoProbe();
    void monitorShowsLateValues();
    void rawFramedUnderAuto_data();
    void rawFramedUnderAuto();
    void interruptedWriteIsReported();

private:
    // The link arguments for `medium` ("tcp" or "serial"); empty (after QSKIP) if impossible.
    QStringList link(const QString &medium);

    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::shared_ptr<QProcess> m_socat;
    std::unique_ptr<QTemporaryDir> m_dir;
    int m_holdFd = -1;
};

void TestDelivery::init()
{
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_server = std::make_unique<SimServer>(m_plc.get());
    m_server->setStation(9);
}

void TestDelivery::cleanup()
{
#ifdef Q_OS_UNIX
    if (m_holdFd >= 0)
        ::close(m_holdFd);
#endif
    m_holdFd = -1;
    m_server.reset();
    m_plc.reset();
    m_socat.reset();
    m_dir.reset();
}

QStringList TestDelivery::link(const QString &medium)
{
    QString error;
    if (medium == QLatin1String("tcp")) {
        if (!m_server->listenTcp(0, &error))
            qWarning() << error;
        return {QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:%1").arg(m_server->tcpPort())};
    }
#ifndef Q_OS_UNIX
    return {}; // pty pairs are Unix; tools/windows/test.sh checks a Wine COM port instead
#else
    m_dir = std::make_unique<QTemporaryDir>();
    const QString plcSide = m_dir->filePath(QStringLiteral("plc"));
    const QString appSide = m_dir->filePath(QStringLiteral("app"));
    m_socat = startPtyPair(plcSide, appSide);
    if (!m_socat)
        return {};
    SerialSettings serial;
    serial.portName = plcSide;
    if (!m_server->openSerial(serial, &error)) {
        qWarning() << error;
        return {};
    }
    // socat ends when the last holder of a pty closes it: keep the app side open (never read)
    // across the short-lived processes.
    m_holdFd = ::open(QFile::encodeName(appSide).constData(), O_RDWR | O_NOCTTY);
    if (m_holdFd < 0)
        return {};
    return {QStringLiteral("--serial"), appSide};
#endif
}

void TestDelivery::writesReachThePlc_data()
{
    QTest::addColumn<QString>("medium");
    QTest::addColumn<int>("station");
    QTest::addColumn<bool>("chain");
    for (const char *medium : {"tcp", "serial"}) {
        QTest::addRow("%s broadcast", medium) << QString::fromLatin1(medium) << 0 << false;
        QTest::addRow("%s broadcast --then", medium) << QString::fromLatin1(medium) << 0 << true;
        QTest::addRow("%s station 9", medium) << QString::fromLatin1(medium) << 9 << false;
    }
}

// One process per write, each exiting right after it reported "written": the simulator must have
// every frame (before the fix, unsent bytes died with the process).
void TestDelivery::writesReachThePlc()
{
    QFETCH(QString, medium);
    QFETCH(int, station);
    QFETCH(bool, chain);
    const QStringList linkArgs = link(medium);
    if (linkArgs.isEmpty())
        QSKIP("no pty pair (socat missing?)");
    constexpr int processes = 16;
    for (int i = 1; i <= processes; ++i) {
        QStringList args = linkArgs;
        args << QStringLiteral("--protocol") << QStringLiteral("facon")
             << QStringLiteral("--station") << QString::number(station) << QStringLiteral("--json")
             << QStringLiteral("write") << QStringLiteral("R6") << QString::number(i);
        if (chain)
            args << QStringLiteral("--then") << QStringLiteral("write") << QStringLiteral("R7")
                 << QString::number(i);
        const Run r = runCli(args);
        RUN_OK(r);
        QVERIFY2(r.json().contains(QStringLiteral("written")), qPrintable(r.out));
    }
    const auto frames = quint64(processes * (chain ? 2 : 1));
    // The last process has ended: whatever it sent is in the simulator's buffers by now.
    QTRY_COMPARE_WITH_TIMEOUT(m_server->counters().frames, frames, 5000);
    QCOMPARE(m_server->counters().rejected, quint64(0));
    QCOMPARE(m_plc->value(Address::parse("R6").value()), std::optional<std::uint32_t>(processes));
    if (chain)
        QCOMPARE(m_plc->value(Address::parse("R7").value()),
                 std::optional<std::uint32_t>(processes));
}

// D2: an unframed raw frame needs no protocol probe (which asked station 1 and failed).
void TestDelivery::rawUnframedUnderAutoNeedsNoProbe()
{
    const QStringList args
        = link(QStringLiteral("tcp"))
          + QStringList{QStringLiteral("--station"), QStringLiteral("9"), QStringLiteral("--json"),
                        QStringLiteral("raw"), QStringLiteral("02 30 39 34 30 43 46 03")};
    const Run r = runCli(args);
    RUN_OK(r);
    QCOMPARE(r.json().value(QStringLiteral("sent")).toString(),
             QStringLiteral("02 30 39 34 30 43 46 03"));
    QVERIFY2(r.json()
                 .value(QStringLiteral("answer"))
                 .toString()
                 .startsWith(QLatin1String("02 30 39 34 30")),
             qPrintable(r.out));
    QCOMPARE(m_server->counters().frames, quint64(1));
    QCOMPARE(m_server->counters().otherStation, quint64(0));
}

void TestDelivery::monitorShowsLateValues()
{
    // Issue 31: a PLC polled every 100 ms whose answers now and then come 600 ms late (a stalled
    // line): meanwhile the last value read is shown late, with its value, never as fresh. (A line
    // that is always slower than the interval is not "late" every cycle: its period adapts, issue
    // 55; tst_stationhealth slowLineIsNotLateEveryCycle.)
    FaultConfig faults;
    faults.spikeRate = 0.3;
    faults.spikeMs = 600;
    m_server->setFaults(faults);
    m_plc->setValue(Address::parse("R0").value(), 4321);
    const QStringList args
        = link(QStringLiteral("tcp"))
          + QStringList{
              QStringLiteral("--station"), QStringLiteral("9"),        QStringLiteral("--json"),
              QStringLiteral("monitor"),   QStringLiteral("R0"),       QStringLiteral("--interval"),
              QStringLiteral("100"),       QStringLiteral("--cycles"), QStringLiteral("16")};
    const Run r = runCli(args);
    RUN_OK(r);
    int late = 0;
    int good = 0;
    for (const QString &line : r.lines()) {
        const QJsonObject json = QJsonDocument::fromJson(line.toUtf8()).object();
        const QString quality = json.value(QStringLiteral("quality")).toArray().at(0).toString();
        QCOMPARE(json.value(QStringLiteral("values")).toArray().at(0).toInteger(), 4321);
        if (quality == QLatin1String("late"))
            ++late;
        else if (quality == QLatin1String("ok"))
            ++good;
    }
    qInfo("16 lines: %d good, %d late", good, late);
    QVERIFY2(late > 0 && good > 0, qPrintable(r.out));
    QVERIFY2(r.err.contains(QStringLiteral("R0: Late: no new value for ")), qPrintable(r.err));
}

// Issue 32: Ctrl-C while a write is on its way: the write reaches the PLC, and stdout says so
// before the program ends with 130; the next step of the chain does not run.
void TestDelivery::interruptedWriteIsReported()
{
#ifndef Q_OS_UNIX
    QSKIP("SIGINT is Unix's");
#else
    FaultConfig faults;
    faults.latencyMs = 1500; // the answer comes 1.5 s after the question
    m_server->setFaults(faults);
    QProcess p;
    p.start(QStringLiteral(FATEK_CLI_PATH),
            link(QStringLiteral("tcp"))
                + QStringList{QStringLiteral("--station"), QStringLiteral("9"),
                              QStringLiteral("--protocol"), QStringLiteral("facon"),
                              QStringLiteral("--timeout"), QStringLiteral("5000"),
                              QStringLiteral("--json"), QStringLiteral("write"),
                              QStringLiteral("R5"), QStringLiteral("42"), QStringLiteral("--then"),
                              QStringLiteral("read"), QStringLiteral("R6")});
    QVERIFY(p.waitForStarted(10000));
    // Interrupted once the write has reached the simulator, its answer still 1.5 s away.
    QTRY_VERIFY_WITH_TIMEOUT(m_server->counters().frames >= 1, 10000);
    ::kill(static_cast<pid_t>(p.processId()), SIGINT);
    QTRY_VERIFY_WITH_TIMEOUT(p.state() == QProcess::NotRunning, 15000);
    const QString out = QString::fromUtf8(p.readAllStandardOutput());
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QCOMPARE(p.exitCode(), 130);
    QCOMPARE(m_plc->value(Address::parse("R5").value()), std::optional<std::uint32_t>(42));
    QVERIFY2(out.contains(QLatin1String("\"written\":[42]")), qPrintable(out + err));
    QVERIFY2(!out.contains(QLatin1String("R6")), qPrintable(out)); // the chain stopped
    QVERIFY2(err.contains(QLatin1String("Interrupted.")), qPrintable(err));
#endif
}

void TestDelivery::rawFramedUnderAuto_data()
{
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("sentStart");
    // Hex bytes are binary bytes: binary framing (header 51, frame id 10). Text is FACON
    // characters.
    QTest::addRow("hex is binary")
        << QStringLiteral("09 40") << QStringLiteral("51 10 00 02 09 40");
    QTest::addRow("text is FACON") << QStringLiteral("0940") << QStringLiteral("02 30 39 34 30");
}

// D3: the framing follows what was typed, and nothing (no status probe, let alone two) goes
// before the frame.
void TestDelivery::rawFramedUnderAuto()
{
    QFETCH(QString, typed);
    QFETCH(QString, sentStart);
    const QStringList args = link(QStringLiteral("tcp"))
                             + QStringList{QStringLiteral("--station"), QStringLiteral("9"),
                                           QStringLiteral("--json"),    QStringLiteral("raw"),
                                           QStringLiteral("--frame"),   typed};
    const Run r = runCli(args);
    RUN_OK(r);
    QVERIFY2(r.json().value(QStringLiteral("sent")).toString().startsWith(sentStart),
             qPrintable(r.out));
    QVERIFY2(!r.json().value(QStringLiteral("answer")).toString().isEmpty(), qPrintable(r.out));
    QCOMPARE(m_server->counters().frames, quint64(1));
    QCOMPARE(m_server->counters().rejected, quint64(0));
}

QTEST_GUILESS_MAIN(TestDelivery)
#include "tst_delivery.moc"
