// LoopbackDialog against the simulator: a clean series, a series through a lossy link (it must keep
// going), data validation; LoopbackStats arithmetic.
#include "core/session/loopbackstats.h"
#include "tst_tools_fixture.h"
#include "ui/tools/loopbackdialog.h"

#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTest>

using namespace Fatek;
using ToolsTest::Rig;

class TestToolsLoopback : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void cleanup();

    void statsArithmetic();
    void hundredRunsSucceed();
    void everyByteValueOverBinary();
    void keepsGoingAfterErrors();
    void textAndHexData();
    void badDataRefused();
    void stopAndNoConnection();

private:
    Rig m_rig;
    std::unique_ptr<LoopbackDialog> m_dialog;
    void open(LinkSettings::ProtocolChoice protocol = LinkSettings::ProtocolChoice::Facon,
              int timeoutMs = 1000, int retries = 1);
};

void TestToolsLoopback::open(LinkSettings::ProtocolChoice protocol, int timeoutMs, int retries)
{
    m_rig = Rig();
    QVERIFY(m_rig.start(protocol, timeoutMs, retries));
    m_dialog = std::make_unique<LoopbackDialog>();
    m_dialog->setTarget(m_rig.target(1));
    m_dialog->show();
}

void TestToolsLoopback::cleanup()
{
    m_dialog.reset();
    m_rig.link.reset();
    m_rig.server.reset();
    m_rig.plc.reset();
}

void TestToolsLoopback::statsArithmetic()
{
    LoopbackStats s;
    QVERIFY(!s.hasRoundTrips());
    QCOMPARE(s.p99Ms(), 0.0);
    for (int i = 1; i <= 100; ++i)
        s.add(LoopbackStats::Outcome::Success, i);
    s.add(LoopbackStats::Outcome::Mismatch, 1000);
    s.add(LoopbackStats::Outcome::Timeout);
    s.add(LoopbackStats::Outcome::Error);
    QCOMPARE(s.runs(), 103);
    QCOMPARE(s.successes(), 100);
    QCOMPARE(s.mismatches(), 1);
    QCOMPARE(s.timeouts(), 1);
    QCOMPARE(s.errors(), 1);
    QCOMPARE(s.minMs(), 1.0);
    QCOMPARE(s.maxMs(), 1000.0);
    QCOMPARE(s.meanMs(), (5050.0 + 1000.0) / 101.0);
    QCOMPARE(s.p99Ms(), 100.0); // rank ceil(0.99 * 101) = 100
    QVERIFY(s.summary().startsWith(
        QStringLiteral("103 runs: 100 OK, 1 mismatch, 1 timeout, 1 other errors")));
    s.reset();
    QCOMPARE(s.runs(), 0);
}

void TestToolsLoopback::hundredRunsSucceed()
{
    open();
    m_dialog->setDataMode(LoopbackDialog::DataMode::Pattern);
    m_dialog->setPatternLength(256);
    m_dialog->setRepeatCount(100);
    m_dialog->setIntervalMs(0);
    m_dialog->start();
    QVERIFY(m_dialog->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(!m_dialog->isRunning(), 60000);
    QCOMPARE(m_dialog->stats().runs(), 100);
    QCOMPARE(m_dialog->stats().successes(), 100);
    QVERIFY(m_dialog->stats().hasRoundTrips());
    QVERIFY(m_dialog->stats().minMs() <= m_dialog->stats().p99Ms());
    QVERIFY2(m_dialog->totalsText().startsWith(QStringLiteral("100 runs: 100 OK")),
             qPrintable(m_dialog->totalsText()));
    QCOMPARE(m_dialog->messageText(), QStringLiteral("Done."));
    auto *log = m_dialog->findChild<QPlainTextEdit *>(QStringLiteral("runLog"));
    QCOMPARE(log->document()->blockCount(), 100);
}

void TestToolsLoopback::everyByteValueOverBinary()
{
    open(LinkSettings::ProtocolChoice::Binary);
    m_dialog->setDataMode(LoopbackDialog::DataMode::Pattern);
    m_dialog->setPatternLength(256); // 00..FF
    m_dialog->setRepeatCount(5);
    m_dialog->start();
    QTRY_VERIFY_WITH_TIMEOUT(!m_dialog->isRunning(), 30000);
    QCOMPARE(m_dialog->stats().successes(), 5);
}

void TestToolsLoopback::keepsGoingAfterErrors()
{
    open(LinkSettings::ProtocolChoice::Facon, 200, 0);
    FaultConfig faults;
    faults.dropRate = 0.4;
    faults.seed = 7;
    m_rig.server->setFaults(faults);
    m_dialog->setDataMode(LoopbackDialog::DataMode::Pattern);
    m_dialog->setPatternLength(16);
    m_dialog->setRepeatCount(20);
    m_dialog->start();
    QTRY_VERIFY_WITH_TIMEOUT(!m_dialog->isRunning(), 60000);
    const LoopbackStats &s = m_dialog->stats();
    QCOMPARE(s.runs(), 20);
    QVERIFY(s.timeouts() > 0);
    QVERIFY(s.successes() > 0);
    QCOMPARE(s.successes() + s.timeouts(), 20);
    QVERIFY(m_dialog->totalsText().contains(QStringLiteral("%1 timeout").arg(s.timeouts())));
    QVERIFY(m_dialog->findChild<QLabel *>(QStringLiteral("totals"))->property("error").toBool());
}

void TestToolsLoopback::textAndHexData()
{
    open(LinkSettings::ProtocolChoice::Binary);
    m_dialog->setDataMode(LoopbackDialog::DataMode::Hex);
    m_dialog->setData(QStringLiteral("00 02 03 FF 55 AA"));
    m_dialog->setRepeatCount(3);
    m_dialog->start();
    QTRY_VERIFY_WITH_TIMEOUT(!m_dialog->isRunning(), 30000);
    QCOMPARE(m_dialog->stats().successes(), 3);

    m_dialog->setDataMode(LoopbackDialog::DataMode::Text);
    m_dialog->setData(QStringLiteral("Hello PLC"));
    m_dialog->start();
    QTRY_VERIFY_WITH_TIMEOUT(!m_dialog->isRunning(), 30000);
    QCOMPARE(m_dialog->stats().successes(), 3);

    m_dialog->setDataMode(LoopbackDialog::DataMode::Pattern);
    m_dialog->setPatternLength(0); // empty test data is legal
    m_dialog->setRepeatCount(2);
    m_dialog->start();
    QTRY_VERIFY_WITH_TIMEOUT(!m_dialog->isRunning(), 30000);
    QCOMPARE(m_dialog->stats().successes(), 2);
}

void TestToolsLoopback::badDataRefused()
{
    open();
    m_dialog->setDataMode(LoopbackDialog::DataMode::Hex);
    m_dialog->setData(QStringLiteral("01 2"));
    m_dialog->start();
    QVERIFY(!m_dialog->isRunning());
    QVERIFY2(m_dialog->messageText().contains(QStringLiteral("Odd number")),
             qPrintable(m_dialog->messageText()));
    // FACON carries printable characters only.
    m_dialog->setData(QStringLiteral("02 03"));
    m_dialog->start();
    QVERIFY(!m_dialog->isRunning());
    QVERIFY2(m_dialog->messageText().contains(QStringLiteral("printable")),
             qPrintable(m_dialog->messageText()));
    m_dialog->setDataMode(LoopbackDialog::DataMode::Text);
    m_dialog->setData(QString(300, QLatin1Char('A')));
    m_dialog->start();
    QVERIFY(!m_dialog->isRunning());
    QVERIFY2(m_dialog->messageText().contains(QStringLiteral("256")),
             qPrintable(m_dialog->messageText()));
}

void TestToolsLoopback::stopAndNoConnection()
{
    open();
    m_dialog->setRepeatCount(1000000);
    m_dialog->setIntervalMs(50);
    m_dialog->start();
    QTRY_VERIFY_WITH_TIMEOUT(m_dialog->stats().runs() >= 2, 30000);
    m_dialog->stop();
    QVERIFY(!m_dialog->isRunning());
    const int runs = m_dialog->stats().runs();
    QTest::qWait(300);
    QCOMPARE(m_dialog->stats().runs(), runs);
    QVERIFY(m_dialog->messageText().startsWith(QStringLiteral("Stopped")));

    m_dialog->setTarget(PlcTarget());
    QVERIFY(!m_dialog->findChild<QPushButton *>(QStringLiteral("startButton"))->isEnabled());
    m_dialog->start();
    QVERIFY(!m_dialog->isRunning());
}

QTEST_MAIN(TestToolsLoopback)
#include "tst_tools_loopback.moc"
