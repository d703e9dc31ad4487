// fatek-cli's changes to a PLC under the one rule (issue 48, docs/reliability.md "Changes to a
// PLC"): a change the PLC carried out but did not answer is said on stderr as unknown at once,
// read back, and ends done (exit 0), not done (3), or still unknown (7), never "failed". Against
// the in-process simulator over loopback TCP, its answers dropped while the CLI runs; what the
// PLC holds and the frames it got are read on the simulator.
#include "core/sim/faultconfig.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"

#include <QProcess>
#include <QTest>

#include <memory>

using namespace Fatek;
using TestUtil::addr;

namespace {

constexpr int Wait = 20000;

FaultConfig mute()
{
    FaultConfig f;
    f.dropRate = 1.0; // every request carried out, none answered
    return f;
}

} // namespace

class TestCliChanges : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();
    void lostAnswerReadBackDone_data();
    void lostAnswerReadBackDone();
    void lostAnswerReadBackNotDone();
    void silentPlcStaysUnknown();

private:
    // Starts fatek-cli on the simulator with `arguments`; stderr collects into m_err.
    void start(const QStringList &arguments);
    int finish();
    int writes(const QString &needle) const;

    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::unique_ptr<QProcess> m_cli;
    QString m_err;
    QStringList m_log;
};

void TestCliChanges::init()
{
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_server = std::make_unique<SimServer>(m_plc.get());
    m_server->setVerbose(true);
    m_log.clear();
    connect(m_server.get(), &SimServer::logLine, this,
            [this](const QString &line) { m_log.append(line); });
    QString error;
    QVERIFY2(m_server->listenTcp(0, &error), qPrintable(error));
}

void TestCliChanges::cleanup()
{
    if (m_cli && m_cli->state() != QProcess::NotRunning) {
        m_cli->kill();
        m_cli->waitForFinished(5000);
    }
    m_cli.reset();
    m_server.reset();
    m_plc.reset();
}

void TestCliChanges::start(const QStringList &arguments)
{
    m_err.clear();
    m_cli = std::make_unique<QProcess>();
    connect(m_cli.get(), &QProcess::readyReadStandardError, this,
            [this] { m_err += QString::fromUtf8(m_cli->readAllStandardError()); });
    m_cli->start(QStringLiteral(FATEK_CLI_PATH),
                 QStringList{QStringLiteral("--tcp"),
                             QStringLiteral("127.0.0.1:%1").arg(m_server->tcpPort()),
                             QStringLiteral("--protocol"), QStringLiteral("facon"),
                             QStringLiteral("--timeout"), QStringLiteral("300"),
                             QStringLiteral("--retries"), QStringLiteral("2")}
                     + arguments);
    QVERIFY(m_cli->waitForStarted(10000));
}

int TestCliChanges::finish()
{
    QDeadlineTimer deadline(Wait);
    while (m_cli->state() != QProcess::NotRunning && !deadline.hasExpired())
        QTest::qWait(10);
    if (m_cli->state() != QProcess::NotRunning)
        return -1;
    m_err += QString::fromUtf8(m_cli->readAllStandardError());
    return m_cli->exitStatus() == QProcess::NormalExit ? m_cli->exitCode() : -2;
}

int TestCliChanges::writes(const QString &needle) const
{
    return static_cast<int>(m_log.filter(needle).size());
}

void TestCliChanges::lostAnswerReadBackDone_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("logged"); // what the simulator logs for the change
    QTest::newRow("write") << QStringList{QStringLiteral("write"), QStringLiteral("R50"),
                                          QStringLiteral("3333")}
                           << QStringLiteral("write R50 = 0x0D05");
    QTest::newRow("set") << QStringList{QStringLiteral("set"), QStringLiteral("M5")}
                         << QStringLiteral("set M5");
    QTest::newRow("stop") << QStringList{QStringLiteral("stop")} << QStringLiteral("STOP");
}

void TestCliChanges::lostAnswerReadBackDone()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, logged);
    m_plc->setRunning(true);
    m_server->setFaults(mute());
    start(arguments);
    QTRY_VERIFY2_WITH_TIMEOUT(m_err.contains(QStringLiteral("Outcome unknown")), qPrintable(m_err),
                              Wait);
    QVERIFY2(m_err.contains(QStringLiteral("may have been carried out")), qPrintable(m_err));
    m_server->setFaults({});
    QCOMPARE(finish(), 0);
    QVERIFY2(m_err.contains(QStringLiteral("Done: confirmed by reading it back")),
             qPrintable(m_err));
    QCOMPARE(writes(logged), 1); // sent once although --retries 2
}

void TestCliChanges::lostAnswerReadBackNotDone()
{
    m_server->setFaults(mute());
    start({QStringLiteral("write"), QStringLiteral("R51"), QStringLiteral("3333")});
    QTRY_VERIFY2_WITH_TIMEOUT(m_err.contains(QStringLiteral("Outcome unknown")), qPrintable(m_err),
                              Wait);
    m_plc->setValue(addr("R51"), 12); // the ladder wrote it since
    m_server->setFaults({});
    QCOMPARE(finish(), 3);
    QVERIFY2(m_err.contains(QStringLiteral("Not done: read back afterwards")), qPrintable(m_err));
}

void TestCliChanges::silentPlcStaysUnknown()
{
    m_server->setFaults(mute());
    start({QStringLiteral("write"), QStringLiteral("R52"), QStringLiteral("7")});
    QCOMPARE(finish(), 7);
    QVERIFY2(m_err.contains(QStringLiteral("Outcome unknown")), qPrintable(m_err));
    QVERIFY2(m_err.contains(QStringLiteral("still unknown")), qPrintable(m_err));
    QVERIFY2(!m_err.contains(QStringLiteral("failed")), qPrintable(m_err));
    QCOMPARE(writes(QStringLiteral("write R52")), 1);
    QCOMPARE(m_plc->value(addr("R52")), std::optional<std::uint32_t>(7));
}

QTEST_GUILESS_MAIN(TestCliChanges)
#include "tst_cli_changes.moc"
