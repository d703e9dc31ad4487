// fatek-cli checkout (issue 53) point by point, the built program against a fatek-sim child, its
// answers on standard input (--yes): inputs one at a time with crossed wiring, skip, fail, defer
// and a remark; a resumed run asking only what is untested; the outputs' answers; analog checks
// with as-found and as-left readings on three points in a row; points the PLC refuses; the
// report's people, the punch list and CRLF; the exit codes. Inputs are actuated and registers
// set in the simulator by a fatek-cli of the test's own; what is forced is read from the
// simulator, never taken from what the checkout says.
#include "checkoutcli.h"
#include "simchild.h"
#include "testutil.h"

#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using TestUtil::CheckoutCli;
using TestUtil::SavedCheckout;
using TestUtil::savedCheckout;

class TestCliCheckoutPoints : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void inputsOneAtATime();
    void interruptAtInputRecordsNothing();
    void outputAnswers();
    void analogAsFoundAsLeft();
    void refusedPointsNamed();
    void reportPeoplePunchListCrlf();
    void punchCheckedBeforeForcing();
    void punchOnAFailingDeviceFollowsOnStdout();
    void notApplicableIsDone();

private:
    // Starts the simulator (STOP) and `fatek-cli checkout PLAN --save FILE --report report.csv
    // EXTRA` against it.
    void startCheckout(CheckoutCli &cli, const QString &plan, const QStringList &extra = {});
    // A fatek-cli of the test's own on the simulator (set X3, write R300 0...).
    bool sim(const QStringList &command);
    // Turns an input on and waits until the checkout file has its rising edge (or, when it is
    // not the input under test, until the checkout said `crossed`), then off.
    bool actuate(CheckoutCli &cli, const QString &input, int point, const QString &crossed = {});
    std::vector<int> forcedY(int count)
    {
        return m_sim->forced(QStringLiteral(FATEK_CLI_PATH), QStringLiteral("Y0"), count);
    }
    QString report() const { return m_dir.filePath(QStringLiteral("report.csv")); }

    QTemporaryDir m_dir;
    QString m_file;
    std::unique_ptr<TestUtil::SimChild> m_sim;
};

void TestCliCheckoutPoints::init()
{
#ifndef Q_OS_UNIX
    QSKIP("Ctrl-C sent to a child: Unix signals");
#endif
    m_file = m_dir.filePath(
        QStringLiteral("%1.checkout.json").arg(QString::fromLatin1(QTest::currentTestFunction())));
}

void TestCliCheckoutPoints::cleanup()
{
    // Nothing forced after any checkout, whatever happened in it.
    if (m_sim)
        QCOMPARE(forcedY(8), std::vector<int>(8, 0));
    m_sim.reset();
}

void TestCliCheckoutPoints::startCheckout(CheckoutCli &cli, const QString &plan,
                                          const QStringList &extra)
{
    if (!m_sim) {
        m_sim = std::make_unique<TestUtil::SimChild>();
        QString error;
        QVERIFY2(m_sim->start(QStringLiteral(FATEK_SIM_PATH), true, {}, &error), qPrintable(error));
    }
    cli.start(m_sim->link()
              + QStringList{QStringLiteral("--timeout"), QStringLiteral("300"),
                            QStringLiteral("--retries"), QStringLiteral("0"),
                            QStringLiteral("--yes"), QStringLiteral("checkout"), plan,
                            QStringLiteral("--save"), m_file, QStringLiteral("--report"), report()}
              + extra);
    QVERIFY(cli.process.waitForStarted(10000));
}

bool TestCliCheckoutPoints::sim(const QStringList &command)
{
    const TestUtil::ProgramRun run
        = TestUtil::runProgram(QStringLiteral(FATEK_CLI_PATH), m_sim->link() + command);
    if (run.code != 0)
        qWarning("fatek-cli %s: exit %d: %s", qPrintable(command.join(QLatin1Char(' '))), run.code,
                 qPrintable(run.err));
    return run.code == 0;
}

bool TestCliCheckoutPoints::actuate(CheckoutCli &cli, const QString &input, int point,
                                    const QString &crossed)
{
    if (!sim({QStringLiteral("set"), input}))
        return false;
    // The runner polls: the edge is waited for, so that on and off are two readings.
    const bool seen
        = crossed.isEmpty() ? QTest::qWaitFor(
              [&] { return savedCheckout(m_file).point(point).contains(QStringLiteral("rose")); },
              CheckoutCli::longWait)
                            : cli.said(crossed);
    return seen && sim({QStringLiteral("reset"), input});
}

// Item 1: the input under test is named; an edge on another one is crossed wiring (said, and
// the point cannot pass clean: it fails once it went on and off, or passes with a remark); a dead
// input is skipped (Enter) and stays untested, one is deferred; then the outputs come. A resumed
// run asks only the untested input, and "na" takes it out.
void TestCliCheckoutPoints::inputsOneAtATime()
{
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("X0..X4, Y0"));
    const auto asked = [](const char *x) {
        return QStringLiteral("Actuate %1 (on, then off); Enter: skip, f [remark]: failed, d "
                              "REASON: deferred, r REMARK: passed with remark, na: not "
                              "applicable, t: test again")
            .arg(QLatin1String(x));
    };
    QVERIFY2(cli.said(asked("X0")), qPrintable(cli.err));
    QVERIFY(actuate(cli, QStringLiteral("X0"), 0));
    QVERIFY2(cli.said(QStringLiteral("X0: Passed")), qPrintable(cli.err));

    // X2 moves while X1 is tested: flagged on X1; the person passes X1 with a remark.
    QVERIFY2(cli.said(asked("X1")), qPrintable(cli.err));
    const QString x2WithX1 = QStringLiteral("X2 changed while testing X1: crossed wiring?");
    QVERIFY(actuate(cli, QStringLiteral("X2"), 2, x2WithX1));
    QVERIFY2(cli.said(x2WithX1, 2), qPrintable(cli.err)); // its fall too
    QVERIFY2(cli.said(asked("X1"), 3), qPrintable(cli.err));
    cli.answer("y\n"); // an input passes by its edges, not by a word
    QVERIFY2(cli.said(QStringLiteral("Not understood: \"y\"")), qPrintable(cli.err));
    cli.answer("r swapped with X2 at terminal 4, fixed\n");
    QVERIFY2(cli.said(QStringLiteral("X1: Passed with remark")), qPrintable(cli.err));

    // X2 is dead: skipped.
    QVERIFY2(cli.said(asked("X2")), qPrintable(cli.err));
    cli.answer("\n");
    QVERIFY2(cli.said(QStringLiteral("X2 skipped: it stays untested.")), qPrintable(cli.err));

    // X0 moves while X3 is tested, then X3 goes on and off: failed, not passed.
    QVERIFY2(cli.said(asked("X3")), qPrintable(cli.err));
    QVERIFY(actuate(cli, QStringLiteral("X0"), 0,
                    QStringLiteral("X0 changed while testing X3: crossed wiring?")));
    QVERIFY(actuate(cli, QStringLiteral("X3"), 3));
    QVERIFY2(cli.said(QStringLiteral("X3: Failed")), qPrintable(cli.err));

    QVERIFY2(cli.said(asked("X4")), qPrintable(cli.err));
    cli.answer("d\n"); // a deferral needs its reason
    QVERIFY2(cli.said(QStringLiteral("X4: \"deferred\" needs the reason")), qPrintable(cli.err));
    cli.answer("d cable not pulled yet\n");
    QVERIFY2(cli.said(QStringLiteral("Skipped, untested: X2.")), qPrintable(cli.err));

    // The output after all, forced on the wire.
    QVERIFY2(cli.said(QStringLiteral("Y0 is ON now. Seen in the field?")), qPrintable(cli.err));
    QCOMPARE(forcedY(8), (std::vector<int>{1, 0, 0, 0, 0, 0, 0, 0}));
    cli.answer("y\n");
    QCOMPARE(cli.exitCode(), 6);
    SavedCheckout saved = savedCheckout(m_file);
    QCOMPARE(saved.results,
             (QStringList{QStringLiteral("passed"), QStringLiteral("passed-with-remark"),
                          QStringLiteral("untested"), QStringLiteral("failed"),
                          QStringLiteral("deferred"), QStringLiteral("passed")}));
    QCOMPARE(saved.point(1).value(QStringLiteral("comment")).toString(),
             QStringLiteral("swapped with X2 at terminal 4, fixed"));
    QCOMPARE(saved.point(3).value(QStringLiteral("changedWith")).toArray().toVariantList(),
             QVariantList{QStringLiteral("X0")});
    QCOMPARE(saved.point(4).value(QStringLiteral("comment")).toString(),
             QStringLiteral("cable not pulled yet"));
    QVERIFY(!saved.point(2).contains(QStringLiteral("rose"))); // X2's edges were X1's flag

    // Resumed: only X2 is asked (Y0 has its answer); "na" takes it out.
    CheckoutCli resumed;
    resumed.start(m_sim->link()
                  + QStringList{QStringLiteral("--yes"), QStringLiteral("checkout"), m_file});
    QVERIFY(resumed.process.waitForStarted(10000));
    QVERIFY2(resumed.said(asked("X2")), qPrintable(resumed.err));
    resumed.answer("na\n");
    QCOMPARE(resumed.exitCode(), 6); // X3 failed, X4 deferred
    for (const char *x : {"X0", "X1", "X3", "X4"})
        QVERIFY2(!resumed.err.contains(QStringLiteral("Actuate %1").arg(QLatin1String(x))),
                 qPrintable(resumed.err));
    QVERIFY2(!resumed.err.contains(QLatin1String("is ON now")), qPrintable(resumed.err));
    saved = savedCheckout(m_file);
    QCOMPARE(saved.results.at(2), QStringLiteral("not-applicable"));
}

// Ctrl-C at an input's question ends the checkout at once and records nothing for the input.
void TestCliCheckoutPoints::interruptAtInputRecordsNothing()
{
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("X0..X1, Y0"));
    QVERIFY2(cli.said(QStringLiteral("Actuate X0 (on, then off)")), qPrintable(cli.err));
    cli.interrupt();
    QCOMPARE(cli.exitCode(), 130);
    QCOMPARE(savedCheckout(m_file).results,
             (QStringList{QStringLiteral("untested"), QStringLiteral("untested"),
                          QStringLiteral("untested")}));
    QVERIFY2(!cli.err.contains(QLatin1String("is ON now")), qPrintable(cli.err));
}

// Item 2: the outputs' answers, each with the output forced on the wire while it is asked:
// r REMARK (seen, with a remark), n COMMENT, a sentence that is no key (asked again, not taken as
// a failure), d REASON, na, y.
void TestCliCheckoutPoints::outputAnswers()
{
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("Y0..Y4"));
    const auto onWire = [this](int y) {
        std::vector<int> expected(8, 0);
        expected[static_cast<std::size_t>(y)] = 1;
        return forcedY(8) == expected;
    };
    QVERIFY2(cli.said(QStringLiteral("Y0 is ON now. Seen in the field? y: yes, n [comment]: no, "
                                     "r REMARK: seen, with a remark, d REASON: deferred, na: not "
                                     "applicable")),
             qPrintable(cli.err));
    QVERIFY(onWire(0));
    cli.answer("r lamp dim, replace bulb\n");
    QVERIFY2(cli.said(QStringLiteral("Y1 is ON now.")), qPrintable(cli.err));
    QVERIFY(onWire(1));
    cli.answer("n no wire at the lamp\n");
    QVERIFY2(cli.said(QStringLiteral("Y2 is ON now.")), qPrintable(cli.err));
    QVERIFY(onWire(2));
    cli.answer("lamp dim\n");
    QVERIFY2(cli.said(QStringLiteral("Not understood: \"lamp dim\"")), qPrintable(cli.err));
    QVERIFY2(cli.said(QStringLiteral("Y2 is ON now."), 2), qPrintable(cli.err));
    QVERIFY(onWire(2));
    cli.answer("d panel not powered\n");
    QVERIFY2(cli.said(QStringLiteral("Y3 is ON now.")), qPrintable(cli.err));
    QVERIFY(onWire(3));
    cli.answer("na\n");
    QVERIFY2(cli.said(QStringLiteral("Y4 is ON now.")), qPrintable(cli.err));
    QVERIFY(onWire(4));
    cli.answer("y\n");
    QCOMPARE(cli.exitCode(), 6);
    const SavedCheckout saved = savedCheckout(m_file);
    QVERIFY(saved.forced.isEmpty());
    QCOMPARE(saved.results,
             (QStringList{QStringLiteral("passed-with-remark"), QStringLiteral("failed"),
                          QStringLiteral("deferred"), QStringLiteral("not-applicable"),
                          QStringLiteral("passed")}));
    QCOMPARE(saved.point(0).value(QStringLiteral("comment")).toString(),
             QStringLiteral("lamp dim, replace bulb"));
    QCOMPARE(saved.point(1).value(QStringLiteral("comment")).toString(),
             QStringLiteral("no wire at the lamp"));
    QCOMPARE(saved.point(2).value(QStringLiteral("comment")).toString(),
             QStringLiteral("panel not powered"));
    // "lamp dim" was not recorded as an attempt.
    QVERIFY(saved.point(2).value(QStringLiteral("earlier")).toArray().isEmpty());
}

// Item 3: three analog points in a row, each checked at 0 and 100 % of 4..20 mA: R300 outside
// at 100 %, adjusted and read as left; R301 within; R302 outside at 0 %, not adjusted (s). Each
// point has its own readings in the file and its own row in the report.
void TestCliCheckoutPoints::analogAsFoundAsLeft()
{
    const QString plan = m_dir.filePath(QStringLiteral("analog.csv"));
    QFile f(plan);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("address,name,comment,group,low,high,tolerance,engLow,engHigh,unit,checks,signed\n"
            "R300,FT300,,,0,32000,0.1,4,20,mA,0/100,\n"
            "R301,FT301,,,0,32000,0.1,4,20,mA,0/100,\n"
            "R302,FT302,,,0,32000,0.1,4,20,mA,0/100,\n");
    f.close();
    CheckoutCli cli;
    startCheckout(cli, plan);
    const auto check = [&](const char *point, const char *percent, const char *raw, int times) {
        if (!cli.said(
                QStringLiteral("Set %1 (FT%2) to %3 %")
                    .arg(QLatin1String(point), QLatin1String(point + 1), QLatin1String(percent)),
                times))
            return false;
        if (!sim({QStringLiteral("write"), QLatin1String(point), QLatin1String(raw)}))
            return false;
        cli.answer("\n");
        return true;
    };
    const QString adjust = QStringLiteral("Adjust the transmitter and press Enter to read it as "
                                          "left, or s to go on.");
    QVERIFY2(check("R300", "0", "0", 1), qPrintable(cli.err));
    QVERIFY2(check("R300", "100", "30000", 1), qPrintable(cli.err)); // 19 mA
    QVERIFY2(cli.said(adjust), qPrintable(cli.err));
    QVERIFY(sim({QStringLiteral("write"), QStringLiteral("R300"), QStringLiteral("31990")}));
    cli.answer("\n");
    QVERIFY2(cli.said(QStringLiteral("R300 (FT300) at 100 %, as left: ")), qPrintable(cli.err));
    QVERIFY2(check("R301", "0", "100", 1), qPrintable(cli.err));
    QVERIFY2(check("R301", "100", "31900", 1), qPrintable(cli.err));
    QVERIFY2(check("R302", "0", "1000", 1), qPrintable(cli.err)); // 4.5 mA
    QVERIFY2(cli.said(adjust, 2), qPrintable(cli.err));
    cli.answer("s\n");
    QVERIFY2(check("R302", "100", "32000", 1), qPrintable(cli.err));
    QCOMPARE(cli.exitCode(), 6); // R302 failed
    for (const char *line :
         {"R300 (FT300): Passed", "R301 (FT301): Passed", "R302 (FT302): Failed"})
        QCOMPARE(cli.err.count(QLatin1String(line)), 1);

    const SavedCheckout saved = savedCheckout(m_file);
    QCOMPARE(saved.results, (QStringList{QStringLiteral("passed"), QStringLiteral("passed"),
                                         QStringLiteral("failed")}));
    const auto readings = [&saved](int point) {
        QStringList list;
        for (const QJsonValue &v : saved.point(point).value(QStringLiteral("readings")).toArray()) {
            const QJsonObject r = v.toObject();
            list << QStringLiteral("%1:%2:%3")
                        .arg(r.value(QStringLiteral("percent")).toInt())
                        .arg(r.value(QStringLiteral("asFound")).toInt())
                        .arg(r.contains(QStringLiteral("asLeft"))
                                 ? QString::number(r.value(QStringLiteral("asLeft")).toInt())
                                 : QStringLiteral("-"));
        }
        return list;
    };
    QCOMPARE(readings(0),
             (QStringList{QStringLiteral("0:0:-"), QStringLiteral("100:30000:31990")}));
    QCOMPARE(readings(1), (QStringList{QStringLiteral("0:100:-"), QStringLiteral("100:31900:-")}));
    QCOMPARE(readings(2), (QStringList{QStringLiteral("0:1000:-"), QStringLiteral("100:32000:-")}));

    // The report: one row per point with its own result.
    QFile csv(report());
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'));
    const auto row = [&lines](const QString &address) {
        const QStringList found
            = lines.filter(QRegularExpression(QStringLiteral("^%1,").arg(address)));
        return found.size() == 1 ? found.first() : QString();
    };
    QVERIFY2(row(QStringLiteral("R300")).contains(QLatin1String(",Passed,")),
             qPrintable(lines.join('\n')));
    QVERIFY2(row(QStringLiteral("R301")).contains(QLatin1String(",Passed,")),
             qPrintable(lines.join('\n')));
    QVERIFY2(row(QStringLiteral("R302")).contains(QLatin1String(",Failed,")),
             qPrintable(lines.join('\n')));
}

// Item 4: X9999 on an FBs: named, exit 2, nothing forced (Y0 is in the plan).
void TestCliCheckoutPoints::refusedPointsNamed()
{
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("X0..X1, Y0, X9999"));
    QCOMPARE(cli.exitCode(), 2);
    QVERIFY2(cli.err.contains(QLatin1String("The PLC refuses X9999")), qPrintable(cli.err));
    QVERIFY2(cli.err.contains(QLatin1String("Nothing was forced.")), qPrintable(cli.err));
    QVERIFY2(!cli.err.contains(QLatin1String("Actuate")), qPrintable(cli.err));
    QVERIFY2(!cli.err.contains(QLatin1String("is ON now")), qPrintable(cli.err));
}

// Item 5: the document's identity and the signatories in the file (and so the report), the punch
// list written as CSV, and --crlf: Windows line ends, the byte order mark always.
void TestCliCheckoutPoints::reportPeoplePunchListCrlf()
{
    const QString punch = m_dir.filePath(QStringLiteral("punch.csv"));
    CheckoutCli cli;
    startCheckout(
        cli, QStringLiteral("Y0..Y1"),
        {QStringLiteral("--document"), QStringLiteral("SAT-0042"), QStringLiteral("--revision"),
         QStringLiteral("B"), QStringLiteral("--engineer"), QStringLiteral("Ann Wu"),
         QStringLiteral("--company"), QStringLiteral("Wu Automation"), QStringLiteral("--witness"),
         QStringLiteral("Bo Chen"), QStringLiteral("--witness-company"),
         QStringLiteral("Plant Ops"), QStringLiteral("--customer-signatory"),
         QStringLiteral("Lin Mei"), QStringLiteral("--punch"), punch, QStringLiteral("--crlf")});
    QVERIFY2(cli.said(QStringLiteral("Y0 is ON now.")), qPrintable(cli.err));
    cli.answer("n lamp holder broken\n");
    QVERIFY2(cli.said(QStringLiteral("Y1 is ON now.")), qPrintable(cli.err));
    cli.answer("y\n");
    QCOMPARE(cli.exitCode(), 6);
    const QJsonObject info = savedCheckout(m_file).file.value(QStringLiteral("info")).toObject();
    QCOMPARE(info.value(QStringLiteral("documentId")).toString(), QStringLiteral("SAT-0042"));
    QCOMPARE(info.value(QStringLiteral("revision")).toString(), QStringLiteral("B"));
    QCOMPARE(info.value(QStringLiteral("engineerCompany")).toString(),
             QStringLiteral("Wu Automation"));
    QCOMPARE(info.value(QStringLiteral("witness")).toString(), QStringLiteral("Bo Chen"));
    QCOMPARE(info.value(QStringLiteral("witnessCompany")).toString(), QStringLiteral("Plant Ops"));
    QCOMPARE(info.value(QStringLiteral("customerSignatory")).toString(), QStringLiteral("Lin Mei"));

    for (const QString &path : {punch, report()}) {
        QFile f(path);
        QVERIFY2(f.open(QIODevice::ReadOnly), qPrintable(path));
        const QByteArray data = f.readAll();
        QVERIFY2(data.startsWith("\xEF\xBB\xBF"), qPrintable(path));
        QVERIFY2(data.contains("\r\n"), qPrintable(path));
        QCOMPARE(data.count("\n"), data.count("\r\n"));
    }
    QFile f(punch);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(f.readAll());
    QVERIFY2(text.contains(QLatin1String("Y0"))
                 && text.contains(QLatin1String("lamp holder broken")),
             qPrintable(text));
    QVERIFY2(!text.contains(QLatin1String("Y1")), qPrintable(text));
    QFile r(report());
    QVERIFY(r.open(QIODevice::ReadOnly));
    QVERIFY(r.readAll().contains("SAT-0042"));
}

// Item 5: a punch list that cannot be written is said before anything is forced.
void TestCliCheckoutPoints::punchCheckedBeforeForcing()
{
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("Y0..Y1"),
                  {QStringLiteral("--punch"), m_dir.filePath(QStringLiteral("no/such/punch.csv"))});
    cli.answer("y\ny\n");
    QCOMPARE(cli.exitCode(), 1);
    QVERIFY2(cli.err.contains(QLatin1String("Nothing was forced")), qPrintable(cli.err));
    QVERIFY2(!cli.err.contains(QLatin1String("is ON now")), qPrintable(cli.err));
    QVERIFY(!QFile::exists(m_file)
            || savedCheckout(m_file).results.count(QStringLiteral("untested")) == 2);
}

// Issue 57: a punch list whose device fails at the end (a link to /dev/full) follows on standard
// output, which is no file: it stays without the byte order mark the file would have had (a guard:
// QString::fromUtf8 already drops the mark there).
void TestCliCheckoutPoints::punchOnAFailingDeviceFollowsOnStdout()
{
    if (!QFileInfo::exists(QStringLiteral("/dev/full")))
        QSKIP("no /dev/full");
    const QString punch = m_dir.filePath(QStringLiteral("full-punch.csv"));
    QVERIFY(QFile::link(QStringLiteral("/dev/full"), punch));
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("Y0..Y1"), {QStringLiteral("--punch"), punch});
    QVERIFY2(cli.said(QStringLiteral("Y0 is ON now.")), qPrintable(cli.err));
    cli.answer("n lamp holder broken\n");
    QVERIFY2(cli.said(QStringLiteral("Y1 is ON now.")), qPrintable(cli.err));
    cli.answer("y\n");
    QCOMPARE(cli.exitCode(), 1);
    QVERIFY2(cli.err.contains(QLatin1String("The punch list follows on standard output")),
             qPrintable(cli.err));
    const QByteArray out = cli.process.readAllStandardOutput();
    QVERIFY2(out.startsWith("# Punch list\n"), out.constData());
    QVERIFY(out.contains("lamp holder broken"));
    QVERIFY(!out.contains("\xEF\xBB\xBF"));
}

// Item 6: not applicable is done (exit 0); deferred is not (exit 6, as failed and untested).
void TestCliCheckoutPoints::notApplicableIsDone()
{
    {
        CheckoutCli cli;
        startCheckout(cli, QStringLiteral("Y0..Y1"));
        cli.answer("y\nna\n");
        QCOMPARE(cli.exitCode(), 0);
        QCOMPARE(savedCheckout(m_file).results,
                 (QStringList{QStringLiteral("passed"), QStringLiteral("not-applicable")}));
    }
    QFile::remove(m_file);
    CheckoutCli cli;
    startCheckout(cli, QStringLiteral("Y0..Y1"));
    cli.answer("y\nd spare, no lamp fitted\n");
    QCOMPARE(cli.exitCode(), 6);
    QCOMPARE(savedCheckout(m_file).results,
             (QStringList{QStringLiteral("passed"), QStringLiteral("deferred")}));
}

QTEST_GUILESS_MAIN(TestCliCheckoutPoints)
#include "tst_cli_checkout_points.moc"
