// The I/O checkout (issue 36) against the in-process simulator over loopback TCP: a 16-input,
// 8-output, 2-analog checkout through CheckoutRunner with the inputs actuated here and the
// outputs answered here, its CSV and PDF reports (read back with pdftotext); a link killed with an
// output forced; a restart with a file that records a forced output; operator mode; crossed
// wiring; a save on a full device. What is forced is checked in the simulator's own memory.
#include "checkoutfixture.h"
#include "core/commission/checkoutfile.h"
#include "core/commission/checkoutplan.h"
#include "core/commission/checkoutreport.h"
#include "core/commission/checkoutrunner.h"
#include "core/commission/commissionmessages.h"
#include "core/qtbridge/qtmessage.h"
#include "core/session/session.h"
#include "core/sim/modelprofile.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "core/watch/symboltable.h"
#include "pdftext.h"
#include "report/checkoutpdf.h"
#include "report/reporttranslator.h"
#include "testutil.h"

#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <memory>

using namespace Fatek;
using TestUtil::addr;

namespace {

const char *planCsv = "address,name,comment,group,low,high,tolerance\n"
                      "X0..X15\n";

// 16 inputs, 8 outputs, 2 analog channels.
CheckoutPlan fullPlan()
{
    QString csv = QStringLiteral("address,name,comment,group,low,high,tolerance\n");
    for (int i = 0; i < 16; ++i)
        csv += QStringLiteral("X%1,SW_%1,switch %1,cabinet A\n").arg(i);
    for (int i = 0; i < 8; ++i)
        csv += QStringLiteral("Y%1,LAMP_%1,\"lamp %1, red\",cabinet B\n").arg(i);
    csv += QStringLiteral("R100,PT_1,pressure,analog,4000,20000,50,,,,0/100\n");
    csv += QStringLiteral("D200,TT_1,temperature,analog,0,32000,100,,,,0/100\n");
    auto plan = CheckoutPlan::fromCsv(csv);
    Q_ASSERT(plan.ok());
    CheckoutPlan p = plan.value();
    p.info.project = QStringLiteral("Line 3 conveyor");
    p.info.customer = QStringLiteral("ACME Foods");
    p.info.engineer = QStringLiteral("Lin");
    return p;
}

// The PDF as a reader gets its text (tests/pdftext.h).
QString pdfText(const QString &pdf)
{
    return PdfText::plain(pdf);
}

} // namespace

class TestCheckout : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void planFromRangesNamesAndCsv();
    void planRefusesOtherElements();
    void fileRoundTrip();
    void fullCheckoutAndReports();
    void crossedWiringFlagged();
    void linkKilledWithOutputForced();
    void restartReleasesRecordedForcedOutput();
    void refusedInReadOnly();
    void asksBeforeOutputsInRun();
    void saveOnFullDeviceIsAnError();
    void reportKeepsSignaturesTogether();

private:
    void startRunner(CheckoutRunner &runner, const CheckoutPlan &plan, const QString &file = {})
    {
        m_sim.startRunner(runner, plan, file);
    }
    void actuate(CheckoutRunner &runner, const char *input) { m_sim.actuate(runner, input); }
    QString freeFile(const char *name) const { return m_sim.freeFile(name); }

    CheckoutSim m_sim;
    SimulatedPlc *m_plc = nullptr;
    SimServer *m_server = nullptr;
    Session *m_session = nullptr;
};

void TestCheckout::init()
{
    m_sim.open();
    m_plc = m_sim.plc.get();
    m_server = m_sim.server.get();
    m_session = m_sim.session.get();
}

void TestCheckout::cleanup()
{
    m_sim.close();
}

void TestCheckout::planFromRangesNamesAndCsv()
{
    SymbolTable names;
    names.insert(addr("X1"), {QStringLiteral("A1_START"), QStringLiteral("start button")});
    names.insert(addr("Y2"), {QStringLiteral("A1_LAMP"), QStringLiteral("lamp")});
    names.insert(addr("Y3"), {QStringLiteral("B2_VALVE"), QString()});
    names.insert(addr("M7"), {QStringLiteral("A1_FLAG"), QString()});
    const auto ranges = CheckoutPlan::fromRanges(QStringLiteral("X0..X47, Y0..Y31"), &names);
    QVERIFY(ranges.ok());
    QCOMPARE(ranges->points.size(), std::size_t(80));
    QCOMPARE(ranges->indexesOf(CheckoutKind::Input).size(), std::size_t(48));
    QCOMPARE(ranges->points[1].name, QStringLiteral("A1_START"));
    QCOMPARE(ranges->points[1].description, QStringLiteral("start button"));

    const auto byPrefix = CheckoutPlan::fromSymbols(names, QStringLiteral("A1"));
    QVERIFY(byPrefix.ok());
    QCOMPARE(byPrefix->points.size(), std::size_t(2)); // M7 is not an I/O point
    QCOMPARE(byPrefix->points[0].group, QStringLiteral("A1"));
    QCOMPARE(byPrefix->points[1].kind, CheckoutKind::Output);
    QVERIFY(!CheckoutPlan::fromSymbols(names, QStringLiteral("ZZ")).ok());

    const CheckoutPlan full = fullPlan();
    QCOMPARE(full.points.size(), std::size_t(26));
    QCOMPARE(full.points[16].description, QStringLiteral("lamp 0, red"));
    QCOMPARE(full.points[24].analog.rawHigh, 20000.0);
    QCOMPARE(full.points[24].analog.engHigh, 20000.0); // no engineering units: the raw values
    QCOMPARE(full.points[24].analog.tolerance, 50.0);
    QCOMPARE(full.points[24].analog.checks, (std::vector<double>{0, 100}));
    // An analog point without its range is refused, with the line.
    const auto noRange = CheckoutPlan::fromCsv(QStringLiteral("R5,level\n"));
    QVERIFY(!noRange.ok());
    QCOMPARE(noRange.error().message.id, MessageId(MsgId::CheckoutCsvLine));
    QVERIFY(!CheckoutPlan::fromCsv(QString::fromLatin1(planCsv)).ok()); // a range is not a line
}

void TestCheckout::planRefusesOtherElements()
{
    const auto m = CheckoutPlan::fromRanges(QStringLiteral("X0..X3, M0"));
    QVERIFY(!m.ok());
    QCOMPARE(m.error().message.id, MessageId(MsgId::CheckoutPlanBadKind));
    const auto twice = CheckoutPlan::fromRanges(QStringLiteral("X0..X3, X2"));
    QVERIFY(!twice.ok());
    QCOMPARE(twice.error().message.id, MessageId(MsgId::CheckoutPlanDuplicate));
}

void TestCheckout::fileRoundTrip()
{
    CheckoutPlan plan = fullPlan();
    plan.forced = {addr("Y3")};
    plan.points[0].result = CheckoutResult::Passed;
    plan.points[0].rose = QDateTime::currentDateTimeUtc();
    plan.points[0].fell = plan.points[0].rose.addMSecs(700);
    plan.points[0].changedWith = {addr("X7")};
    plan.points[16].seen = false;
    plan.points[24].readings = {AnalogReading{0, 4010, {}}};
    plan.points[24].earlier = {CheckoutAttempt{}};
    plan.points[24].earlier[0].result = CheckoutResult::Failed;
    plan.points[24].earlier[0].comment = QStringLiteral("transmitter dead");
    plan.points[24].punch.owner = QStringLiteral("electrician");
    const QString path = freeFile("plan.checkout.json");
    QVERIFY(CheckoutFile::saveToFile(plan, path).ok());
    const auto loaded = CheckoutFile::loadFromFile(path);
    QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().text().c_str());
    QCOMPARE(loaded.value(), plan);
    QVERIFY(!CheckoutFile::load("{\"format\": \"other\"}", path).ok());
}

void TestCheckout::fullCheckoutAndReports()
{
    CheckoutRunner runner;
    const QString file = freeFile("line3.checkout.json");
    runner.setAutoAdvance(true);
    startRunner(runner, fullPlan(), file);
    QCOMPARE(runner.plan().info.plcModel.isEmpty(), false);

    // Inputs: walked in order; each passes on 0->1 and 1->0 and the next one becomes current.
    runner.setCurrentPoint(0);
    for (int i = 0; i < 16; ++i) {
        QCOMPARE(runner.currentPoint(), i);
        const QByteArray name = "X" + QByteArray::number(i);
        actuate(runner, name.constData());
        QTRY_COMPARE_WITH_TIMEOUT(runner.plan().points[static_cast<std::size_t>(i)].result,
                                  CheckoutResult::Passed, 30000);
    }
    QCOMPARE(runner.currentPoint(), -1); // auto-advance walks inputs only: none is left

    // Outputs: one at a time, forced in the simulator while asked, released after the answer.
    QSignalSpy forced(&runner, &CheckoutRunner::outputForced);
    for (int j = 0; j < 8; ++j) {
        const int index = 16 + j;
        const Address y = runner.plan().points[static_cast<std::size_t>(index)].address;
        runner.forceOutput(index);
        QTRY_COMPARE_WITH_TIMEOUT(forced.count(), j + 1, 30000);
        QCOMPARE(m_plc->isDisabled(y), std::optional<bool>(true));
        QCOMPARE(m_plc->value(y), std::optional<std::uint32_t>(1));
        QCOMPARE(runner.plan().forced, std::vector<Address>{y});
        // The file says what is forced while it is.
        QCOMPARE(CheckoutFile::loadFromFile(file)->forced, std::vector<Address>{y});
        if (j == 3)
            runner.answerOutput(false, QStringLiteral("lamp broken"));
        else
            runner.answerOutput(true);
        QTRY_VERIFY_WITH_TIMEOUT(m_plc->isDisabled(y) == std::optional<bool>(false), 30000);
        QCOMPARE(m_plc->value(y), std::optional<std::uint32_t>(0));
        QTRY_VERIFY_WITH_TIMEOUT(!runner.hasForced(), 30000);
    }

    // Analog: both ends; R100 within tolerance, D200's high end 300 off.
    const int r100 = runner.plan().indexOf(addr("R100"));
    const int d200 = runner.plan().indexOf(addr("D200"));
    const auto readings = [&runner](int index) {
        return runner.plan().points[static_cast<std::size_t>(index)].readings.size();
    };
    m_plc->setValue(addr("R100"), 4020);
    QVERIFY(runner.recordAnalog(r100, 0).ok());
    QTRY_COMPARE_WITH_TIMEOUT(readings(r100), std::size_t(1), 30000);
    m_plc->setValue(addr("R100"), 19990);
    QVERIFY(runner.recordAnalog(r100, 1).ok());
    m_plc->setValue(addr("D200"), 40);
    QVERIFY(runner.recordAnalog(d200, 0).ok());
    QTRY_COMPARE_WITH_TIMEOUT(readings(d200), std::size_t(1), 30000);
    m_plc->setValue(addr("D200"), 31700);
    QVERIFY(runner.recordAnalog(d200, 1).ok());
    QTRY_COMPARE_WITH_TIMEOUT(runner.plan().points[static_cast<std::size_t>(d200)].result,
                              CheckoutResult::Failed, 30000);
    QCOMPARE(runner.plan().points[static_cast<std::size_t>(r100)].result, CheckoutResult::Passed);
    QCOMPARE(runner.plan().count(CheckoutResult::Passed), 24);
    QCOMPARE(runner.plan().count(CheckoutResult::Failed), 2);

    runner.stop();
    // The file holds what the runner holds: it resumes.
    const auto saved = CheckoutFile::loadFromFile(file);
    QVERIFY(saved.ok());
    QCOMPARE(saved.value(), runner.plan());

    // CSV report.
    const CheckoutReport report = CheckoutReport::of(runner.plan());
    const QString csv = QString::fromUtf8(report.toCsv());
    const QStringList lines = csv.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QVERIFY2(lines.contains(QStringLiteral("# Project: Line 3 conveyor")), qPrintable(csv));
    QVERIFY2(lines.contains(QStringLiteral("# Customer: ACME Foods")), qPrintable(csv));
    QVERIFY2(lines.contains(QStringLiteral("Point,Name,Group,Kind,Result,Measured,Comment,"
                                           "Tested at,Engineer,Attempts")),
             qPrintable(csv));
    QVERIFY2(csv.contains(QStringLiteral("\nY3,\"LAMP_3 - lamp 3, red\",cabinet B,Output,Failed,"
                                         "not seen in the field,lamp broken,")),
             qPrintable(csv));
    QVERIFY2(csv.contains(QStringLiteral("\nX15,SW_15 - switch 15,cabinet A,Input,Passed,"
                                         "\"0->1 at ")),
             qPrintable(csv));
    QVERIFY2(csv.contains(QStringLiteral("D200,TT_1 - temperature,analog,Analog,Failed,\"0 %: "
                                         "40; 100 %: 31700, expected 32000 (tolerance "
                                         "\u00B1100)\"")),
             qPrintable(csv));
    QVERIFY2(
        lines.last()
            == QStringLiteral("# Summary: 26 points: 24 passed, 0 passed with remark, 2 failed, 0 "
                              "deferred, 0 not applicable, 0 untested."),
        qPrintable(lines.last()));
    // Title, 8 fields, header, 26 points, summary.
    QCOMPARE(lines.size(), 1 + 8 + 1 + 26 + 1);

    // PDF report, in English and in Chinese, read back as text.
    const QString pdf = freeFile("report.pdf");
    QVERIFY(CheckoutPdf::write(report, pdf, {}).ok());
    const QString text = pdfText(pdf);
    for (const char *expected :
         {"I/O checkout report", "Line 3 conveyor", "ACME Foods", "PLC model", "OS version", "X15",
          "Y7", "lamp broken", "D200", "26 points: 24 passed, 0 passed with remark, 2 failed",
          "Commissioning engineer", "Customer representative"})
        QVERIFY2(text.contains(QLatin1String(expected)),
                 qPrintable(QLatin1String(expected) + QLatin1String(" not in:\n") + text));
    QVERIFY2(text.contains(runner.plan().info.plcModel), qPrintable(text));

    ReportTranslator chinese;
    QVERIFY(chinese.setLanguage(QStringLiteral("zh_TW")));
    const QString title = chinese.text(msg<MsgId::ReportTitle>());
    QVERIFY(title != QLatin1String("I/O checkout report"));
    const QString pdfZh = freeFile("report_zh.pdf");
    QVERIFY(CheckoutPdf::write(report, pdfZh, [&chinese](const Message &m) {
                return chinese.text(m);
            }).ok());
    const QString textZh = pdfText(pdfZh);
    QVERIFY2(textZh.contains(chinese.text(msg<MsgId::ReportSignCustomer>())), qPrintable(textZh));
    QVERIFY2(!textZh.contains(QLatin1String("Customer representative")), qPrintable(textZh));
}

void TestCheckout::crossedWiringFlagged()
{
    CheckoutRunner runner;
    startRunner(runner, CheckoutPlan::fromRanges(QStringLiteral("X0..X15")).value());
    QSignalSpy crossed(&runner, &CheckoutRunner::crossedWiring);
    runner.setCurrentPoint(5);
    m_plc->setValue(addr("X7"), 1);
    QTRY_COMPARE_WITH_TIMEOUT(crossed.count(), 1, 30000);
    QCOMPARE(crossed.at(0).at(0).toInt(), 7);
    QCOMPARE(crossed.at(0).at(1).toInt(), 5);
    const Message m = crossed.at(0).at(2).value<Message>();
    QCOMPARE(m.id, MessageId(MsgId::CheckoutCrossedWiring));
    QCOMPARE(englishText(m), QStringLiteral("X7 changed while testing X5: crossed wiring?"));
    const CheckoutPoint &x5 = runner.plan().points[5];
    QCOMPARE(x5.changedWith, std::vector<Address>{addr("X7")});
    QCOMPARE(x5.result, CheckoutResult::Untested); // X5 itself never moved
    QVERIFY(!runner.plan().points[7].rose.isValid());
}

void TestCheckout::linkKilledWithOutputForced()
{
    CheckoutRunner runner;
    const QString file = freeFile("lost.checkout.json");
    startRunner(runner, CheckoutPlan::fromRanges(QStringLiteral("Y0..Y7")).value(), file);
    QSignalSpy forced(&runner, &CheckoutRunner::outputForced);
    QSignalSpy failed(&runner, &CheckoutRunner::failed);
    QSignalSpy leftovers(&runner, &CheckoutRunner::leftoversReleased);
    runner.forceOutput(2);
    QTRY_COMPARE_WITH_TIMEOUT(forced.count(), 1, 30000);
    QCOMPARE(m_plc->isDisabled(addr("Y2")), std::optional<bool>(true));

    // The link dies while the technician looks: the server goes, with its connection.
    m_server->close();
    QTRY_VERIFY_WITH_TIMEOUT(m_session->linkState() != LinkState::Connected, 30000);
    QTRY_VERIFY_WITH_TIMEOUT(!failed.isEmpty(), 30000);
    QCOMPARE(failed.last().at(0).value<ProtocolError>().message.id,
             MessageId(MsgId::CheckoutLinkLost));
    QCOMPARE(runner.outputUnderTest(), -1);
    QVERIFY(runner.hasForced());
    QCOMPARE(CheckoutFile::loadFromFile(file)->forced, std::vector<Address>{addr("Y2")});
    QCOMPARE(m_plc->isDisabled(addr("Y2")), std::optional<bool>(true)); // still, in the PLC

    // Back on the same port: released at once, counted in the simulator's own memory.
    QVERIFY(m_server->listenTcp(m_sim.port));
    QTRY_VERIFY_WITH_TIMEOUT(m_session->linkState() == LinkState::Connected, 60000);
    QTRY_VERIFY_WITH_TIMEOUT(m_plc->isDisabled(addr("Y2")) == std::optional<bool>(false), 60000);
    QCOMPARE(m_plc->value(addr("Y2")), std::optional<std::uint32_t>(0));
    QTRY_VERIFY_WITH_TIMEOUT(!runner.hasForced(), 30000);
    QCOMPARE(leftovers.count(), 1);
    QVERIFY(CheckoutFile::loadFromFile(file)->forced.empty());
    for (std::uint32_t n = 0; n < 256; ++n)
        QCOMPARE(m_plc->isDisabled(Address{ElementType::Y, n}), std::optional<bool>(false));
}

void TestCheckout::restartReleasesRecordedForcedOutput()
{
    // A PC that died with Y5 forced: the PLC still has it, the file says so.
    QVERIFY(m_plc->setDisabled(addr("Y5"), true));
    QVERIFY(m_plc->setValue(addr("Y5"), 1));
    CheckoutPlan plan = CheckoutPlan::fromRanges(QStringLiteral("X0..X3, Y0..Y7")).value();
    plan.forced = {addr("Y5")};
    const QString file = freeFile("crashed.checkout.json");
    QVERIFY(CheckoutFile::saveToFile(plan, file).ok());

    CheckoutRunner runner;
    QSignalSpy leftovers(&runner, &CheckoutRunner::leftoversReleased);
    const auto loaded = CheckoutFile::loadFromFile(file);
    QVERIFY(loaded.ok());
    QVERIFY(!loaded->forced.empty());
    startRunner(runner, loaded.value(), file);
    QTRY_COMPARE_WITH_TIMEOUT(leftovers.count(), 1, 30000);
    QCOMPARE(englishText(leftovers.at(0).at(0).value<Message>()),
             QStringLiteral("Released the outputs the checkout had forced: Y5."));
    QCOMPARE(m_plc->isDisabled(addr("Y5")), std::optional<bool>(false));
    QCOMPARE(m_plc->value(addr("Y5")), std::optional<std::uint32_t>(0));
    QVERIFY(CheckoutFile::loadFromFile(file)->forced.empty());
}

void TestCheckout::refusedInReadOnly()
{
    m_session->setReadOnly(true);
    CheckoutRunner runner;
    startRunner(runner, CheckoutPlan::fromRanges(QStringLiteral("X0..X3, Y0..Y3")).value());
    QSignalSpy failed(&runner, &CheckoutRunner::failed);
    QSignalSpy forced(&runner, &CheckoutRunner::outputForced);
    runner.forceOutput(4);
    QCOMPARE(failed.count(), 1);
    const ProtocolError e = failed.at(0).at(0).value<ProtocolError>();
    QCOMPARE(e.kind, ErrorKind::ReadOnly);
    QCOMPARE(e.message.id, MessageId(MsgId::CheckoutReadOnly));
    QVERIFY(!runner.hasForced());
    QTest::qWait(200);
    QCOMPARE(forced.count(), 0);
    QCOMPARE(m_plc->isDisabled(addr("Y0")), std::optional<bool>(false));
    // Inputs are still checked in operator mode (nothing is written).
    actuate(runner, "X2");
    QTRY_COMPARE_WITH_TIMEOUT(runner.plan().points[2].result, CheckoutResult::Passed, 30000);
}

void TestCheckout::asksBeforeOutputsInRun()
{
    m_plc->setRunning(true);
    CheckoutRunner runner;
    startRunner(runner, CheckoutPlan::fromRanges(QStringLiteral("Y0..Y3")).value());
    QVERIFY(runner.isPlcRunning());
    QSignalSpy ask(&runner, &CheckoutRunner::runConfirmationNeeded);
    QSignalSpy forced(&runner, &CheckoutRunner::outputForced);
    QSignalSpy failed(&runner, &CheckoutRunner::failed);
    runner.forceOutput(1);
    QTRY_COMPARE_WITH_TIMEOUT(ask.count(), 1, 30000);
    // A question, not a failure: "nothing was forced" would be wrong once it is answered yes.
    QCOMPARE(failed.count(), 0);
    QCOMPARE(englishText(ask.at(0).at(1).value<Message>()).left(74),
             QStringLiteral("The PLC is in RUN: its program drives the outputs too. Force Y1 on "
                            "anyway?"));
    QCOMPARE(m_plc->isDisabled(addr("Y1")), std::optional<bool>(false));
    QVERIFY(!runner.hasForced());
    runner.allowOutputsInRun(true);
    runner.forceOutput(1);
    QTRY_COMPARE_WITH_TIMEOUT(forced.count(), 1, 30000);
    QCOMPARE(m_plc->isDisabled(addr("Y1")), std::optional<bool>(true));
    runner.stop(); // no answer: released all the same
    QTRY_VERIFY_WITH_TIMEOUT(m_plc->isDisabled(addr("Y1")) == std::optional<bool>(false), 30000);
    QCOMPARE(runner.plan().points[1].result, CheckoutResult::Untested);
}

void TestCheckout::saveOnFullDeviceIsAnError()
{
    if (!QFileInfo(QStringLiteral("/dev/full")).exists())
        QSKIP("no /dev/full here");
    CheckoutPlan plan = CheckoutPlan::fromRanges(QStringLiteral("X0..X3, Y0")).value();
    const Status s = CheckoutFile::saveToFile(plan, QStringLiteral("/dev/full"));
    QVERIFY(!s.ok());
    QCOMPARE(s.error().message.id, MessageId(MsgId::CheckoutFileCannotWrite));

    // The runner says so, and forces nothing it could not record.
    CheckoutRunner runner;
    QSignalSpy saveFailed(&runner, &CheckoutRunner::saveFailed);
    QSignalSpy failed(&runner, &CheckoutRunner::failed);
    startRunner(runner, plan, QStringLiteral("/dev/full"));
    QVERIFY(saveFailed.count() >= 1);
    QVERIFY(runner.saveError().has_value());
    runner.forceOutput(4);
    QTRY_VERIFY_WITH_TIMEOUT(!failed.isEmpty(), 30000);
    QCOMPARE(failed.last().at(0).value<ProtocolError>().message.id,
             MessageId(MsgId::CheckoutFileCannotWrite));
    QTest::qWait(200);
    QCOMPARE(m_plc->isDisabled(addr("Y0")), std::optional<bool>(false));
    QVERIFY(!runner.hasForced());
}

// The signatures' heading never stays behind at the foot of a page without its lines: for plans
// of every other length up to two pages and a half, the page that says "Signatures" has the lines
// too. (Without the rule, 3 to 4 lengths in a row near each page's end failed: 19-21, 51-54.)
void TestCheckout::reportKeepsSignaturesTogether()
{
    int pagesSeen = 1;
    for (int inputs = 1; inputs <= 69; inputs += 2) {
        const Result<CheckoutPlan> plan
            = CheckoutPlan::fromRanges(QStringLiteral("X0..X%1").arg(inputs - 1));
        QVERIFY(plan.ok());
        const QString pdf = freeFile("pages.pdf");
        QVERIFY(CheckoutPdf::write(CheckoutReport::of(*plan), pdf, {}).ok());
        const QString text = pdfText(pdf);
        if (inputs == 1) // one point, not "1 points"
            QVERIFY2(
                text.contains(QLatin1String("1 point: 0 passed, 0 passed with remark, 0 failed")),
                qPrintable(text));
        const QStringList pages = text.split(QLatin1Char('\f'), Qt::SkipEmptyParts);
        pagesSeen = std::max(pagesSeen, int(pages.size()));
        bool together = false;
        for (const QString &page : pages) {
            if (page.contains(QLatin1String("Signatures")))
                together = page.contains(QLatin1String("Customer representative"));
        }
        QVERIFY2(together, qPrintable(QStringLiteral("%1 inputs:\n").arg(inputs)
                                      + pages.join(QStringLiteral("\n---- next page ----\n"))));
    }
    QVERIFY(pagesSeen >= 2); // the plans did reach a page's end
}

QTEST_MAIN(TestCheckout)
#include "tst_checkout.moc"
