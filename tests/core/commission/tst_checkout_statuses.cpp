// Issue 53: the checkout's record as loop-check sheets keep it, against the in-process simulator
// over loopback TCP. Statuses with their remark or reason, re-tests that keep the earlier
// attempts, crossed wiring that cannot pass clean, the punch list, analog points in engineering
// units checked at five points with as-found and as-left readings (signed and 32-bit), points the
// PLC refuses named at start, checkout files read strictly (unknown and duplicate keys, version 1),
// and the CSV a spreadsheet on Windows opens.
#include "checkoutfixture.h"
#include "core/commission/checkoutfile.h"
#include "core/commission/checkoutreport.h"
#include "core/commission/commissionmessages.h"
#include "core/watch/watchmessages.h"

using namespace Fatek;
using TestUtil::addr;

namespace {

CheckoutPoint &pointOf(CheckoutRunner &runner, const char *address)
{
    const int i = runner.plan().indexOf(addr(address));
    Q_ASSERT(i >= 0);
    return const_cast<CheckoutPoint &>(runner.plan().points[static_cast<std::size_t>(i)]);
}

QString errorText(const Status &s)
{
    return s ? QString() : englishText(s.error().message);
}

} // namespace

class TestCheckoutStatuses : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init() { m_sim.open(); }
    void cleanup() { m_sim.close(); }

    void statusesNeedTheirText();
    void blankEngineerIsRefused();
    void forcedOutputPassedWithRemark();
    void retestKeepsEarlierAttempts();
    void crossedWiringCannotPassClean();
    void punchListOwnerAndCloseOut();
    void analogFivePointsInEngineeringUnits();
    void analogSignedAnd32Bit();
    void analogWithoutScaleCannotPass();
    void pointsThePlcRefusesAreNamed();
    void fileRefusesUnknownAndDuplicateKeys();
    void fileVersionOneStillReads();
    void csvForSpreadsheets();

private:
    CheckoutSim m_sim;
};

void TestCheckoutStatuses::statusesNeedTheirText()
{
    CheckoutRunner runner;
    m_sim.startRunner(runner, CheckoutPlan::fromRanges(QStringLiteral("X0..X3")).value());
    // Passed with remark and deferred say why, or are refused with nothing recorded.
    Status s = runner.record(0, CheckoutResult::PassedWithRemark);
    QCOMPARE(errorText(s), QStringLiteral("X0: \"passed with remark\" needs the remark"));
    s = runner.record(1, CheckoutResult::Deferred, QStringLiteral("  "));
    QCOMPARE(errorText(s), QStringLiteral("X1: \"deferred\" needs the reason"));
    QCOMPARE(runner.plan().count(CheckoutResult::Untested), 4);

    QVERIFY(runner.record(0, CheckoutResult::PassedWithRemark, QStringLiteral("lamp dim")).ok());
    QVERIFY(runner.record(1, CheckoutResult::Deferred, QStringLiteral("sensor not fitted")).ok());
    QVERIFY(runner.record(2, CheckoutResult::NotApplicable).ok());
    QVERIFY(runner.record(3, CheckoutResult::Failed, QStringLiteral("no signal")).ok());
    const CheckoutPlan &plan = runner.plan();
    QCOMPARE(plan.points[0].result, CheckoutResult::PassedWithRemark);
    QCOMPARE(plan.points[0].comment, QStringLiteral("lamp dim"));
    QCOMPARE(plan.points[0].engineer, QStringLiteral("Lin"));
    QVERIFY(plan.points[0].time.isValid());
    const CheckoutReport report = CheckoutReport::of(plan);
    QCOMPARE(englishText(report.summary),
             QStringLiteral("4 points: 0 passed, 1 passed with remark, 1 failed, 1 deferred, 1 not "
                            "applicable, 0 untested."));
    // Failed and deferred are the punch list; passed with remark and N/A are done.
    QCOMPARE(plan.punchList(), (std::vector<int>{1, 3}));
    QVERIFY(isCheckoutDone(CheckoutResult::NotApplicable));
    QVERIFY(!isCheckoutDone(CheckoutResult::Deferred));
}

void TestCheckoutStatuses::blankEngineerIsRefused()
{
    CheckoutRunner runner;
    runner.setSession(m_sim.session.get());
    runner.setPlan(CheckoutPlan::fromRanges(QStringLiteral("X0")).value());
    runner.setEngineer(QStringLiteral("  "));
    QSignalSpy failed(&runner, &CheckoutRunner::failed);
    runner.start();
    QCOMPARE(failed.count(), 1);
    QCOMPARE(englishText(failed.at(0).at(0).value<ProtocolError>().message),
             QStringLiteral("Name the engineer who records the results: the report says who "
                            "tested each point."));
    QVERIFY(!runner.isRunning());
    // The plan's engineer is enough.
    CheckoutPlan plan = runner.plan();
    plan.info.engineer = QStringLiteral("Lin");
    runner.setPlan(plan);
    QSignalSpy started(&runner, &CheckoutRunner::started);
    runner.start();
    QTRY_COMPARE_WITH_TIMEOUT(started.count(), 1, 30000);
}

void TestCheckoutStatuses::forcedOutputPassedWithRemark()
{
    // "Seen, but the lamp is dim": recorded on the forced output, which is released at once.
    CheckoutRunner runner;
    m_sim.startRunner(runner, CheckoutPlan::fromRanges(QStringLiteral("Y0..Y1")).value());
    QSignalSpy forced(&runner, &CheckoutRunner::outputForced);
    runner.forceOutput(0);
    QTRY_COMPARE_WITH_TIMEOUT(forced.count(), 1, 30000);
    QCOMPARE(m_sim.plc->isDisabled(addr("Y0")), std::optional<bool>(true));
    QVERIFY(runner.record(0, CheckoutResult::PassedWithRemark, QStringLiteral("lamp dim")).ok());
    QCOMPARE(runner.outputUnderTest(), -1);
    QTRY_VERIFY_WITH_TIMEOUT(m_sim.plc->isDisabled(addr("Y0")) == std::optional<bool>(false),
                             30000);
    QCOMPARE(m_sim.plc->value(addr("Y0")), std::optional<std::uint32_t>(0));
    QTRY_VERIFY_WITH_TIMEOUT(!runner.hasForced(), 30000);
    const CheckoutPoint &y0 = pointOf(runner, "Y0");
    QCOMPARE(y0.result, CheckoutResult::PassedWithRemark);
    QCOMPARE(y0.seen, std::optional<bool>(true));
    QCOMPARE(y0.attempts(), 1);
}

void TestCheckoutStatuses::retestKeepsEarlierAttempts()
{
    CheckoutRunner runner;
    const QString file = m_sim.freeFile("retest.checkout.json");
    m_sim.startRunner(runner, CheckoutPlan::fromRanges(QStringLiteral("X0..X1")).value(), file);
    runner.setCurrentPoint(0);
    QVERIFY(runner.record(0, CheckoutResult::Failed, QStringLiteral("no signal")).ok());
    // A failed input takes no edge until it is tested again.
    m_sim.plc->setValue(addr("X0"), 1);
    QTest::qWait(400);
    QVERIFY(!pointOf(runner, "X0").rose.isValid());
    m_sim.plc->setValue(addr("X0"), 0);
    QTest::qWait(400);

    runner.retest(0);
    QCOMPARE(pointOf(runner, "X0").result, CheckoutResult::Untested);
    QCOMPARE(pointOf(runner, "X0").earlier.size(), std::size_t(1));
    m_sim.actuate(runner, "X0");
    QTRY_COMPARE_WITH_TIMEOUT(pointOf(runner, "X0").result, CheckoutResult::Passed, 30000);
    const CheckoutPoint &x0 = pointOf(runner, "X0");
    QCOMPARE(x0.attempts(), 2);
    QCOMPARE(x0.earlier[0].result, CheckoutResult::Failed);
    QCOMPARE(x0.earlier[0].comment, QStringLiteral("no signal"));
    QCOMPARE(x0.earlier[0].engineer, QStringLiteral("Lin"));
    QVERIFY(x0.comment.isEmpty()); // the new attempt has its own comment
    // A result by hand on a tested point is a new attempt too.
    QVERIFY(runner.record(0, CheckoutResult::PassedWithRemark, QStringLiteral("ok, slow")).ok());
    QCOMPARE(pointOf(runner, "X0").attempts(), 3);

    // The file keeps the history; the report shows the last result and the count.
    const auto saved = CheckoutFile::loadFromFile(file);
    QVERIFY2(saved.ok(), saved.ok() ? "" : saved.error().text().c_str());
    QCOMPARE(saved.value(), runner.plan());
    const CheckoutReport report = CheckoutReport::of(runner.plan());
    QCOMPARE(report.rows[0].result, CheckoutResult::PassedWithRemark);
    QCOMPARE(report.rows[0].attempts, 3);
    QCOMPARE(report.rows[1].attempts, 0);
}

void TestCheckoutStatuses::crossedWiringCannotPassClean()
{
    CheckoutRunner runner;
    runner.setAutoAdvance(true);
    m_sim.startRunner(runner, CheckoutPlan::fromRanges(QStringLiteral("X0..X3")).value());
    runner.setCurrentPoint(0);
    QSignalSpy crossed(&runner, &CheckoutRunner::crossedWiring);
    m_sim.plc->setValue(addr("X3"), 1);
    QTRY_COMPARE_WITH_TIMEOUT(crossed.count(), 1, 30000);
    // Passed by hand: refused while the flag stands.
    const Status s = runner.record(0, CheckoutResult::Passed);
    QCOMPARE(errorText(s), QStringLiteral("X0 cannot pass clean: X3 changed while it was tested "
                                          "(crossed wiring?). Re-test it, or pass it with a "
                                          "remark."));
    // Both of its own edges: it fails, it does not pass.
    m_sim.actuate(runner, "X0");
    QTRY_COMPARE_WITH_TIMEOUT(pointOf(runner, "X0").result, CheckoutResult::Failed, 30000);
    QCOMPARE(englishText(pointOf(runner, "X0").measured()).contains(QLatin1String("X3")), true);
    // The engineer looked: passed with a remark, a new attempt.
    QVERIFY(runner
                .record(0, CheckoutResult::PassedWithRemark,
                        QStringLiteral("X3 shares the common; checked, fine"))
                .ok());
    QCOMPARE(pointOf(runner, "X0").attempts(), 2);
}

void TestCheckoutStatuses::punchListOwnerAndCloseOut()
{
    CheckoutRunner runner;
    m_sim.startRunner(runner, CheckoutPlan::fromRanges(QStringLiteral("X0..X2")).value());
    QVERIFY(!runner.setPunchOwner(0, QStringLiteral("Wang")).ok()); // not on the list
    QVERIFY(runner.record(0, CheckoutResult::Failed, QStringLiteral("wire loose")).ok());
    QVERIFY(runner.record(1, CheckoutResult::Deferred, QStringLiteral("panel not powered")).ok());
    QVERIFY(runner.setPunchOwner(0, QStringLiteral("Wang (electrician)")).ok());
    // Still failing: not closed out.
    QCOMPARE(errorText(runner.closePunch(0, {})),
             QStringLiteral("X0 still fails: re-test it before its punch item is closed out"));
    runner.retest(0);
    m_sim.actuate(runner, "X0");
    QTRY_COMPARE_WITH_TIMEOUT(pointOf(runner, "X0").result, CheckoutResult::Passed, 30000);
    QVERIFY(runner.closePunch(0, QStringLiteral("Chen")).ok());

    const CheckoutReport report = CheckoutReport::of(runner.plan());
    QCOMPARE(report.punch.size(), std::size_t(2));
    QCOMPARE(report.punch[0].address, QStringLiteral("X0"));
    QCOMPARE(report.punch[0].result, CheckoutResult::Passed);
    QCOMPARE(report.punch[0].remark, QStringLiteral("wire loose")); // what was mended
    QCOMPARE(report.punch[0].owner, QStringLiteral("Wang (electrician)"));
    QVERIFY(report.punch[0].closed);
    QVERIFY(englishText(report.punch[0].state).startsWith(QLatin1String("closed ")));
    QVERIFY(englishText(report.punch[0].state).endsWith(QLatin1String(" by Chen")));
    QCOMPARE(report.punch[1].remark, QStringLiteral("panel not powered"));
    QCOMPARE(englishText(report.punch[1].state), QStringLiteral("open"));
    const QString csv = QString::fromUtf8(report.punchCsv());
    QVERIFY2(csv.contains(QStringLiteral("\nPoint,Name,Result,Comment,Owner,State\n")),
             qPrintable(csv));
    QVERIFY2(csv.contains(QStringLiteral("\nX1,,Deferred,panel not powered,,open\n")),
             qPrintable(csv));
}

void TestCheckoutStatuses::analogFivePointsInEngineeringUnits()
{
    // A 4..20 mA transmitter on a 0..32000 input, good within 0.1 mA, checked at five points.
    auto plan
        = CheckoutPlan::fromCsv(QStringLiteral("R100,PT_1,pressure,analog,0,32000,0.1,4,20,mA\n"));
    QVERIFY2(plan.ok(), plan.ok() ? "" : plan.error().text().c_str());
    const AnalogScale &scale = plan->points[0].analog;
    QCOMPARE(scale.checks, (std::vector<double>{0, 25, 50, 75, 100}));
    QCOMPARE(scale.expected(25), 8.0);
    CheckoutRunner runner;
    m_sim.startRunner(runner, plan.value());
    QSignalSpy recorded(&runner, &CheckoutRunner::analogRecorded);
    // 4.00, 8.00, 12.3 (off: 600 counts), 16.0, 20.0 mA as found.
    const std::uint32_t found[] = {0, 8000, 16600, 24000, 32000};
    for (int check = 0; check < 5; ++check) {
        m_sim.plc->setValue(addr("R100"), found[check]);
        QVERIFY(runner.recordAnalog(0, check).ok());
        QTRY_COMPARE_WITH_TIMEOUT(recorded.count(), check + 1, 30000);
        QCOMPARE(recorded.last().at(1).toInt(), check);
    }
    QCOMPARE(pointOf(runner, "R100").result, CheckoutResult::Failed);
    QCOMPARE(englishText(pointOf(runner, "R100").measured()),
             QStringLiteral("0 %: 4.00 mA; 25 %: 8.00 mA; 50 %: 12.30 mA, expected 12.00 mA; "
                            "75 %: 16.00 mA; 100 %: 20.00 mA (tolerance \u00B10.10 mA)"));
    // Adjusted at mid-scale, read as left: the same attempt, now passed.
    m_sim.plc->setValue(addr("R100"), 16010);
    QVERIFY(runner.recordAnalog(0, 2, true).ok());
    QTRY_COMPARE_WITH_TIMEOUT(recorded.count(), 6, 30000);
    const CheckoutPoint &r100 = pointOf(runner, "R100");
    QCOMPARE(r100.result, CheckoutResult::Passed);
    QCOMPARE(r100.attempts(), 1);
    QCOMPARE(r100.readings[2].asFound, std::optional<std::int64_t>(16600));
    QCOMPARE(r100.readings[2].asLeft, std::optional<std::int64_t>(16010));
    QVERIFY(englishText(r100.measured())
                .contains(QLatin1String("50 %: found 12.30 mA, left 12.01 mA")));
    // By hand it neither passes nor fails: the readings decide.
    QCOMPARE(errorText(runner.record(0, CheckoutResult::Passed)),
             QStringLiteral("R100 passes or fails by what is read: read it at each check"));
    // As left before as found is refused.
    QVERIFY(runner.record(0, CheckoutResult::NotApplicable).ok());
    QCOMPARE(errorText(runner.recordAnalog(0, 4, true)),
             QStringLiteral("R100 at 100 %: read the value as found before the value as left"));
}

void TestCheckoutStatuses::analogSignedAnd32Bit()
{
    // -100.0..100.0 % on a signed register (-1000..1000), and a 32-bit counter (DR10).
    auto plan = CheckoutPlan::fromCsv(
        QStringLiteral("D300,SPEED,,,-1000,1000,0.5,-100,100,%,0/50/100,signed\n"
                       "DR10,FLOW,,,0,100000,1%,0,500,l/min,0/100\n"));
    QVERIFY2(plan.ok(), plan.ok() ? "" : plan.error().text().c_str());
    CheckoutRunner runner;
    m_sim.startRunner(runner, plan.value());
    QSignalSpy recorded(&runner, &CheckoutRunner::analogRecorded);
    const std::pair<int, std::uint32_t> d300[] = {{0, 0xFC18u /* -1000 */}, {1, 3}, {2, 1000}};
    for (const auto &[check, value] : d300) {
        m_sim.plc->setValue(addr("D300"), value);
        QVERIFY(runner.recordAnalog(0, check).ok());
        QTRY_VERIFY_WITH_TIMEOUT(!recorded.isEmpty() && recorded.last().at(1).toInt() == check,
                                 30000);
    }
    QCOMPARE(pointOf(runner, "D300").readings[0].asFound, std::optional<std::int64_t>(-1000));
    QCOMPARE(pointOf(runner, "D300").result, CheckoutResult::Passed);
    // 32 bits: 99000 counts is 495 l/min, 1 % of the 500 l/min span is 5.
    recorded.clear();
    m_sim.plc->setValue(addr("DR10"), 200);
    QVERIFY(runner.recordAnalog(1, 0).ok());
    QTRY_COMPARE_WITH_TIMEOUT(recorded.count(), 1, 30000);
    m_sim.plc->setValue(addr("DR10"), 99000);
    QVERIFY(runner.recordAnalog(1, 1).ok());
    QTRY_COMPARE_WITH_TIMEOUT(recorded.count(), 2, 30000);
    QCOMPARE(pointOf(runner, "DR10").readings[1].asFound, std::optional<std::int64_t>(99000));
    QCOMPARE(pointOf(runner, "DR10").result, CheckoutResult::Passed);
}

void TestCheckoutStatuses::analogWithoutScaleCannotPass()
{
    // Typed as a range: no expected values (issue 53: it "passed" at 0..0).
    CheckoutRunner runner;
    m_sim.startRunner(runner, CheckoutPlan::fromRanges(QStringLiteral("X0, R100")).value());
    QCOMPARE(errorText(runner.recordAnalog(1, 0)),
             QStringLiteral("R100 has no expected values: give its scale (raw and engineering low "
                            "and high) in the plan before it can pass"));
    QCOMPARE(pointOf(runner, "R100").result, CheckoutResult::Untested);
    // And a plan CSV refuses an analog line without them.
    QVERIFY(!CheckoutPlan::fromCsv(QStringLiteral("R100,level,,,5,5\n")).ok());
}

void TestCheckoutStatuses::pointsThePlcRefusesAreNamed()
{
    CheckoutRunner runner;
    runner.setSession(m_sim.session.get());
    runner.setPlan(CheckoutPlan::fromRanges(QStringLiteral("X0..X1, X9999, Y0")).value());
    runner.setEngineer(QStringLiteral("Lin"));
    QSignalSpy refused(&runner, &CheckoutRunner::refused);
    QSignalSpy started(&runner, &CheckoutRunner::started);
    QSignalSpy early(&runner, &CheckoutRunner::failed);
    runner.start();
    // Space pressed while every point is still being read: refused, or Y0 would be forced
    // before the PLC refuses X9999 ("Nothing was forced").
    runner.forceOutput(runner.plan().indexOf(addr("Y0")));
    QCOMPARE(early.count(), 1);
    QCOMPARE(early.at(0).at(0).value<ProtocolError>().message.id,
             MessageId(MsgId::CheckoutNotRunning));
    QTRY_COMPARE_WITH_TIMEOUT(refused.count(), 1, 30000);
    const QString text = englishText(refused.at(0).at(0).value<Message>());
    QVERIFY2(text.startsWith(QLatin1String("The PLC refuses X9999 (")), qPrintable(text));
    QVERIFY2(
        text.endsWith(QLatin1String("): 1 point to take out of the plan. Nothing was forced.")),
        qPrintable(text));
    QVERIFY(!runner.isRunning());
    QTest::qWait(300);
    QCOMPARE(started.count(), 0);
    QSignalSpy failed(&runner, &CheckoutRunner::failed);
    runner.forceOutput(runner.plan().indexOf(addr("Y0")));
    QCOMPARE(failed.count(), 1);
    QCOMPARE(failed.at(0).at(0).value<ProtocolError>().message.id,
             MessageId(MsgId::CheckoutNotRunning));
    QTest::qWait(300);
    QCOMPARE(m_sim.plc->isDisabled(addr("Y0")), std::optional<bool>(false));
}

void TestCheckoutStatuses::fileRefusesUnknownAndDuplicateKeys()
{
    CheckoutPlan plan = CheckoutPlan::fromRanges(QStringLiteral("X0..X1")).value();
    QByteArray good = CheckoutFile::save(plan);
    QVERIFY(CheckoutFile::load(good, QStringLiteral("a.json")).ok());
    // A misspelt key in a point: refused with the point named and the key it likely means.
    QByteArray typo = good;
    typo.replace("\"result\": \"untested\"", "\"reslt\": \"passed\"");
    auto loaded = CheckoutFile::load(typo, QStringLiteral("a.json"));
    QVERIFY(!loaded.ok());
    QVERIFY2(englishText(loaded.error().message).contains(QLatin1String("point 1 (X0)")),
             qPrintable(englishText(loaded.error().message)));
    QVERIFY2(englishText(loaded.error().message).contains(QLatin1String("\"reslt\"")),
             qPrintable(englishText(loaded.error().message)));
    // A key given twice.
    QByteArray twice = good;
    twice.replace("\"kind\": \"input\",", "\"kind\": \"input\", \"kind\": \"output\",");
    loaded = CheckoutFile::load(twice, QStringLiteral("a.json"));
    QVERIFY(!loaded.ok());
    QVERIFY2(englishText(loaded.error().message).contains(QLatin1String("duplicate key \"kind\"")),
             qPrintable(englishText(loaded.error().message)));
    // An unknown key at the top and in the info.
    QByteArray top = good;
    top.replace("\"forced\":", "\"forcd\": [], \"forced\":");
    QVERIFY(!CheckoutFile::load(top, QStringLiteral("a.json")).ok());
    QByteArray info = good;
    info.replace("\"project\":", "\"projekt\": \"x\", \"project\":");
    loaded = CheckoutFile::load(info, QStringLiteral("a.json"));
    QVERIFY(!loaded.ok());
    QVERIFY2(englishText(loaded.error().message).contains(QLatin1String("info: ")),
             qPrintable(englishText(loaded.error().message)));
}

void TestCheckoutStatuses::fileVersionOneStillReads()
{
    const QByteArray v1 = R"({"format": "fatek-checkout", "version": 1,
        "info": {"project": "Line 3", "customer": "ACME", "station": 1, "plcModel": "",
                 "osVersion": "", "created": "2026-11-25T19:55:00.000Z", "engineer": "Lin"},
        "forced": ["Y3"],
        "points": [
          {"address": "X0", "kind": "input", "result": "skipped"},
          {"address": "Y3", "kind": "output", "result": "failed", "seen": false,
           "comment": "lamp broken", "time": "2026-11-25T20:00:00.000Z", "engineer": "Lin"},
          {"address": "R100", "kind": "analog", "result": "passed", "expectedLow": 4000,
           "expectedHigh": 20000, "tolerance": 50, "lowValue": 4010, "highValue": 19990}]})";
    const auto loaded = CheckoutFile::load(v1, QStringLiteral("old.json"));
    QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().text().c_str());
    const CheckoutPlan &plan = loaded.value();
    QCOMPARE(plan.forced, std::vector<Address>{addr("Y3")});
    QCOMPARE(plan.points[0].result, CheckoutResult::Deferred);
    QCOMPARE(plan.points[1].seen, std::optional<bool>(false));
    const AnalogScale &a = plan.points[2].analog;
    QCOMPARE(a.rawLow, 4000.0);
    QCOMPARE(a.engHigh, 20000.0);
    QCOMPARE(a.checks, (std::vector<double>{0, 100}));
    QCOMPARE(plan.points[2].readings.size(), std::size_t(2));
    QCOMPARE(plan.points[2].readings[1].asFound, std::optional<std::int64_t>(19990));
    // Saved again as version 2, and read back the same.
    const QByteArray v2 = CheckoutFile::save(plan);
    QVERIFY(v2.contains("\"version\": 2"));
    QCOMPARE(CheckoutFile::load(v2, QStringLiteral("new.json")).value(), plan);
    // "skipped" is version 1's word only.
    QByteArray skipped = v2;
    skipped.replace("\"result\": \"deferred\"", "\"result\": \"skipped\"");
    QVERIFY(!CheckoutFile::load(skipped, QStringLiteral("new.json")).ok());
}

void TestCheckoutStatuses::csvForSpreadsheets()
{
    CheckoutPlan plan = CheckoutPlan::fromRanges(QStringLiteral("X0..X1")).value();
    plan.points[0].result = CheckoutResult::Failed;
    plan.points[0].comment = QStringLiteral("端子鬆脫");
    const CheckoutReport report = CheckoutReport::of(plan);
    const QByteArray lf = report.toCsv();
    // UTF-8 with its byte order mark: Excel on Windows reads the Chinese right.
    QVERIFY(lf.startsWith("\xEF\xBB\xBF# I/O checkout report\n"));
    QVERIFY(!lf.contains('\r'));
    QVERIFY(QString::fromUtf8(lf).contains(QStringLiteral("端子鬆脫")));
    const QByteArray crlf = report.toCsv({}, CheckoutReport::LineEnds::CrLf);
    QVERIFY(crlf.startsWith("\xEF\xBB\xBF# I/O checkout report\r\n"));
    QCOMPARE(crlf.count("\r\n"), lf.count('\n'));
    QCOMPARE(crlf.count('\n'), lf.count('\n'));
    const QByteArray punch = report.punchCsv({}, CheckoutReport::LineEnds::CrLf);
    QVERIFY(punch.startsWith("\xEF\xBB\xBF# Punch list\r\n"));
}

QTEST_GUILESS_MAIN(TestCheckoutStatuses)
#include "tst_checkout_statuses.moc"
