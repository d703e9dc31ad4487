// fatek-cli checkout (issue 48) as a technician runs it, the built program against a fatek-sim
// child, its answers written to its standard input (--yes): Ctrl-C at a question, an empty line
// and the end of input, the simulator stopped (SIGSTOP) while an output is released, the PLC in
// RUN. What is forced is read from the simulator with `fatek-cli forced` after every test, never
// taken from what the checkout says.
#include "checkoutcli.h"
#include "simchild.h"
#include "testutil.h"

#include <QTemporaryDir>
#include <QTest>

using TestUtil::CheckoutCli;
using TestUtil::SavedCheckout;
using TestUtil::savedCheckout;

class TestCliCheckout : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void interruptAtQuestionReleasesAtOnce();
    void noAnswerRecordsNothing();
    void releaseRetriedUntilConfirmed();
    void leftForcedOnlyWhenTheUserSaysSo();
    void plcInRunSaysWhatHappens();

private:
    // Starts the simulator (STOP unless `running`) and `fatek-cli checkout PLAN` against it.
    void startCheckout(CheckoutCli &cli, const QString &plan, bool running = false);
    std::vector<int> forcedInSim();

    QTemporaryDir m_dir;
    QString m_file;
    std::unique_ptr<TestUtil::SimChild> m_sim;
};

void TestCliCheckout::init()
{
#ifndef Q_OS_UNIX
    QSKIP("Ctrl-C and SIGSTOP sent to a child: Unix signals");
#endif
    m_file = m_dir.filePath(
        QStringLiteral("%1.checkout.json").arg(QString::fromLatin1(QTest::currentTestFunction())));
}

void TestCliCheckout::cleanup()
{
    // fatek-cli forced is empty after every checkout, whatever happened in it.
    if (m_sim && m_sim->resume())
        QCOMPARE(forcedInSim(), std::vector<int>(4, 0));
    m_sim.reset();
}

void TestCliCheckout::startCheckout(CheckoutCli &cli, const QString &plan, bool running)
{
    m_sim = std::make_unique<TestUtil::SimChild>();
    QString error;
    QVERIFY2(m_sim->start(QStringLiteral(FATEK_SIM_PATH), !running, {}, &error), qPrintable(error));
    cli.start(m_sim->link()
              + QStringList{QStringLiteral("--timeout"), QStringLiteral("300"),
                            QStringLiteral("--retries"), QStringLiteral("0"),
                            QStringLiteral("--yes"), QStringLiteral("checkout"), plan,
                            QStringLiteral("--save"), m_file, QStringLiteral("--report"),
                            m_dir.filePath(QStringLiteral("report.csv"))});
    QVERIFY(cli.process.waitForStarted(10000));
}

std::vector<int> TestCliCheckout::forcedInSim()
{
    return m_sim->forced(QStringLiteral(FATEK_CLI_PATH), QStringLiteral("Y0"), 4);
}

// Case 1: Ctrl-C at "Seen in the field?" releases the output at once, records nothing for it, and
// writes the report (exit 130).
void TestCliCheckout::interruptAtQuestionReleasesAtOnce()
{
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("Y0..Y1"));
    QVERIFY2(cli.said(QStringLiteral("Y0 is ON now. Seen in the field? y: yes, n [comment]: no")),
             qPrintable(cli.err));
    QCOMPARE(forcedInSim(), (std::vector<int>{1, 0, 0, 0}));
    cli.interrupt();
    QCOMPARE(cli.exitCode(), 130);
    QCOMPARE(forcedInSim(), std::vector<int>(4, 0));
    const SavedCheckout saved = savedCheckout(m_file);
    QVERIFY(saved.forced.isEmpty());
    QCOMPARE(saved.results, (QStringList{QStringLiteral("untested"), QStringLiteral("untested")}));
    QVERIFY2(!cli.err.contains(QLatin1String("not seen")), qPrintable(cli.err));
    QVERIFY2(cli.err.contains(QLatin1String(
                 "2 points: 0 passed, 0 passed with remark, 0 failed, 0 deferred, 0 not "
                 "applicable, 2 untested.")),
             qPrintable(cli.err));
}

// An empty line is no answer (asked again); the end of input releases the output, which stays
// untested (not "failed").
void TestCliCheckout::noAnswerRecordsNothing()
{
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("Y0..Y1"));
    const QString y0 = QStringLiteral("Y0 is ON now. Seen in the field?");
    QVERIFY2(cli.said(y0), qPrintable(cli.err));
    cli.answer("\n");
    QVERIFY2(cli.said(y0, 2), qPrintable(cli.err));
    cli.answer("y\n");
    QVERIFY2(cli.said(QStringLiteral("Y1 is ON now. Seen in the field?")), qPrintable(cli.err));
    QCOMPARE(forcedInSim(), (std::vector<int>{0, 1, 0, 0}));
    cli.process.closeWriteChannel();
    QCOMPARE(cli.exitCode(), 6); // a point untested
    QVERIFY2(cli.err.contains(
                 QLatin1String("No answer (end of input): Y1 is released and stays untested.")),
             qPrintable(cli.err));
    QCOMPARE(forcedInSim(), std::vector<int>(4, 0));
    const SavedCheckout saved = savedCheckout(m_file);
    QVERIFY(saved.forced.isEmpty());
    QCOMPARE(saved.results, (QStringList{QStringLiteral("passed"), QStringLiteral("untested")}));
}

// Case 2: the simulator stops answering while Y0 is released. The program does not end with Y0
// forced: it asks whether to leave it so, goes on trying, and ends once the PLC confirmed the
// release (exit 3: the link timed out), the file's "forced" list emptied then.
void TestCliCheckout::releaseRetriedUntilConfirmed()
{
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("Y0..Y1"));
    QVERIFY2(cli.said(QStringLiteral("Y0 is ON now. Seen in the field?")), qPrintable(cli.err));
    QVERIFY(m_sim->pause());
    cli.answer("y\n");
    QVERIFY2(cli.said(QStringLiteral("Y0 is still forced in the PLC: the release is tried again "
                                     "until the PLC confirms it. Leave it forced and exit? [y/N]")),
             qPrintable(cli.err));
    QVERIFY2(cli.err.contains(QLatin1String("Releasing Y0 failed")), qPrintable(cli.err));
    QCOMPARE(savedCheckout(m_file).forced, QStringList{QStringLiteral("Y0")});
    QCOMPARE(cli.process.state(), QProcess::Running);

    QVERIFY(m_sim->resume());
    QCOMPARE(cli.exitCode(), 3);
    QVERIFY2(cli.err.contains(QLatin1String("Released the outputs the checkout had forced: Y0.")),
             qPrintable(cli.err));
    QCOMPARE(forcedInSim(), std::vector<int>(4, 0));
    const SavedCheckout saved = savedCheckout(m_file);
    QVERIFY(saved.forced.isEmpty());
    QCOMPARE(saved.results, (QStringList{QStringLiteral("passed"), QStringLiteral("untested")}));
}

// The person chooses to leave the output forced: the program ends non-zero and names it, and the
// file still lists it. (The test then releases it as the message says.)
void TestCliCheckout::leftForcedOnlyWhenTheUserSaysSo()
{
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("Y0..Y1"));
    QVERIFY2(cli.said(QStringLiteral("Y0 is ON now. Seen in the field?")), qPrintable(cli.err));
    QVERIFY(m_sim->pause());
    cli.answer("y\n");
    QVERIFY2(cli.said(QStringLiteral("Leave it forced and exit? [y/N]")), qPrintable(cli.err));
    // A second Ctrl-C does not end it at once: the question is asked again.
    cli.interrupt();
    QVERIFY2(cli.said(QStringLiteral("Leave it forced and exit? [y/N]"), 2), qPrintable(cli.err));
    cli.answer("y\n");
    QCOMPARE(cli.exitCode(), 3);
    QVERIFY2(cli.err.contains(QLatin1String("Left forced in the PLC: Y0.")), qPrintable(cli.err));
    QCOMPARE(savedCheckout(m_file).forced, QStringList{QStringLiteral("Y0")});

    QVERIFY(m_sim->resume());
    const TestUtil::ProgramRun release = TestUtil::runProgram(
        QStringLiteral(FATEK_CLI_PATH),
        m_sim->link()
            + QStringList{QStringLiteral("reset"), QStringLiteral("Y0"), QStringLiteral("--then"),
                          QStringLiteral("enable"), QStringLiteral("Y0")});
    QVERIFY2(release.code == 0, qPrintable(release.err));
}

// Case 3: the PLC in RUN. --yes answers the question, and nothing claims that nothing was forced
// while the output is forced.
void TestCliCheckout::plcInRunSaysWhatHappens()
{
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("Y0"), true);
    QVERIFY2(cli.said(QStringLiteral("Y0 is ON now. Seen in the field?")), qPrintable(cli.err));
    QVERIFY2(!cli.err.contains(QLatin1String("nothing was forced")), qPrintable(cli.err));
    QVERIFY2(cli.err.contains(QLatin1String("The PLC is in RUN: Y0 is forced on all the same "
                                            "(--yes).")),
             qPrintable(cli.err));
    QCOMPARE(forcedInSim(), (std::vector<int>{1, 0, 0, 0}));
    cli.answer("y\n");
    QCOMPARE(cli.exitCode(), 0);
    QCOMPARE(savedCheckout(m_file).results, QStringList{QStringLiteral("passed")});
}

QTEST_GUILESS_MAIN(TestCliCheckout)
#include "tst_cli_checkout.moc"
