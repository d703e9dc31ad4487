// The I/O checkout's releases against a fatek-sim child that stops answering (SIGSTOP: its TCP
// connection stays open, every request times out, as with a PLC that hangs) and comes back
// (SIGCONT): a release that timed out is tried again until the PLC confirms it, said once, and the
// file keeps the output listed as forced until then (issue 48). What is forced is read from the
// simulator by a fatek-cli of the test's own (`forced`), never from the runner.
#include "core/commission/checkoutfile.h"
#include "core/commission/checkoutplan.h"
#include "core/commission/checkoutrunner.h"
#include "core/commission/commissionmessages.h"
#include "core/qtbridge/qtmessage.h"
#include "core/session/session.h"
#include "simchild.h"
#include "testutil.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;
using TestUtil::addr;

namespace {
constexpr int longWait = 30000;
} // namespace

class TestCheckoutRelease : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void releaseRetriedAfterTimeout();

private:
    // Y0..Y3 as the simulator holds them (1: forced).
    std::vector<int> forcedInSim();

    std::unique_ptr<TestUtil::SimChild> m_sim;
    std::unique_ptr<Session> m_session;
    QTemporaryDir m_dir;
};

void TestCheckoutRelease::init()
{
#ifndef Q_OS_UNIX
    QSKIP("stopping the simulator (SIGSTOP) has no Windows counterpart");
#endif
    registerSessionMetaTypes();
    m_sim = std::make_unique<TestUtil::SimChild>();
    QString error;
    QVERIFY2(m_sim->start(QStringLiteral(FATEK_SIM_PATH), true, {}, &error), qPrintable(error));
    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_sim->port(),
                                              LinkSettings::ProtocolChoice::Facon);
    // No retry by the session: the runner's own loop is what is tested.
    settings.timeoutMs = 300;
    settings.retries = 0;
    m_session = std::make_unique<Session>(settings);
    m_session->open();
    QTRY_VERIFY_WITH_TIMEOUT(m_session->linkState() == LinkState::Connected, longWait);
}

void TestCheckoutRelease::cleanup()
{
    m_session.reset();
    // Nothing is left forced in the simulator, whatever the test did.
    if (m_sim && m_sim->resume())
        QCOMPARE(forcedInSim(), std::vector<int>(4, 0));
    m_sim.reset();
}

std::vector<int> TestCheckoutRelease::forcedInSim()
{
    return m_sim->forced(QStringLiteral(FATEK_CLI_PATH), QStringLiteral("Y0"), 4);
}

// The GUI's Space with the simulator stopped (issue 48, case 2): the release times out, is said
// once, and goes on being tried; once the simulator answers again the output is released in the
// PLC, dropped from the file's "forced" list, and the answer given is kept.
void TestCheckoutRelease::releaseRetriedAfterTimeout()
{
    const QString file = m_dir.filePath(QStringLiteral("retry.checkout.json"));
    CheckoutRunner runner;
    runner.setSession(m_session.get());
    runner.setPlan(CheckoutPlan::fromRanges(QStringLiteral("Y0..Y3")).value());
    runner.setFilePath(file);
    runner.setEngineer(QStringLiteral("Lin"));
    runner.setReleaseRetryMs(200);
    QSignalSpy started(&runner, &CheckoutRunner::started);
    QSignalSpy forced(&runner, &CheckoutRunner::outputForced);
    QSignalSpy failed(&runner, &CheckoutRunner::failed);
    QSignalSpy released(&runner, &CheckoutRunner::leftoversReleased);
    runner.start();
    QTRY_COMPARE_WITH_TIMEOUT(started.count(), 1, longWait);
    runner.forceOutput(1);
    QTRY_COMPARE_WITH_TIMEOUT(forced.count(), 1, longWait);
    QCOMPARE(forcedInSim(), (std::vector<int>{0, 1, 0, 0}));

    QVERIFY(m_sim->pause());
    const quint64 timeoutsBefore = m_session->statistics().total.timeouts;
    runner.answerOutput(true);
    QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, longWait);
    const ProtocolError e = failed.at(0).at(0).value<ProtocolError>();
    QCOMPARE(e.message.id, MessageId(MsgId::CheckoutReleaseFailed));
    QVERIFY2(englishText(e.message).contains(QLatin1String("tried again until the PLC confirms")),
             qPrintable(englishText(e.message)));
    QVERIFY(runner.isRetryingRelease());
    QCOMPARE(CheckoutFile::loadFromFile(file)->forced, std::vector<Address>{addr("Y1")});
    // Tried again and again while the simulator is stopped, said once.
    QTRY_VERIFY_WITH_TIMEOUT(m_session->statistics().total.timeouts >= timeoutsBefore + 4,
                             longWait);
    QCOMPARE(failed.count(), 1);
    QVERIFY(runner.hasForced());

    QVERIFY(m_sim->resume());
    QTRY_VERIFY_WITH_TIMEOUT(!runner.hasForced(), longWait);
    QCOMPARE(forcedInSim(), std::vector<int>(4, 0));
    QVERIFY(!runner.isRetryingRelease());
    QCOMPARE(released.count(), 1);
    QCOMPARE(englishText(released.at(0).at(0).value<Message>()),
             QStringLiteral("Released the outputs the checkout had forced: Y1."));
    const auto saved = CheckoutFile::loadFromFile(file);
    QVERIFY(saved.ok());
    QVERIFY(saved->forced.empty());
    QCOMPARE(saved->points[1].result, CheckoutResult::Passed);
    QCOMPARE(failed.count(), 1);
}

QTEST_MAIN(TestCheckoutRelease)
#include "tst_checkout_release.moc"
