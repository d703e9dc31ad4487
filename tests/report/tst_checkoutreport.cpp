// The I/O checkout report as a customer receives it (issue 53): a 96-point plan printed in English
// and in Chinese, read back word by word with where each word is (pdftotext -bbox): every page
// numbered "page N of M" and headed with the project, the column header on every page of rows, no
// row split across two pages, the signatures after the last row, times with their UTC offset, the
// engineer who recorded most, plural words right in the command line's English; the document id and
// revision on every page, the punch list (owner, open or closed) on the summary page, the attempts
// of a re-tested point, the signatories' printed names.

#include "core/commission/checkoutplan.h"
#include "core/commission/checkoutreport.h"
#include "core/commission/commissionmessages.h"
#include "core/qtbridge/qtmessage.h"
#include "pdftext.h"
#include "report/checkoutpdf.h"
#include "report/reporttranslator.h"

#include <QDir>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <ctime>

using namespace Fatek;

namespace {

// 96 points: 48 inputs, 32 outputs, 16 analog; every seventh with a comment long enough to wrap
// over several lines (markers at both ends, so a split row shows as two pages), two failed, six
// not tested, recorded by two engineers from 01:00 UTC on.
CheckoutPlan plan96(const QString &longComment)
{
    CheckoutPlan plan
        = CheckoutPlan::fromRanges(QStringLiteral("X0..X47, Y0..Y31, R100..R115")).value();
    plan.info.project = QStringLiteral("Line 7 packer");
    plan.info.customer = QStringLiteral("ACME Foods");
    plan.info.engineer = QStringLiteral("Boss");
    plan.info.documentId = QStringLiteral("SAT-0427");
    plan.info.revision = QStringLiteral("B");
    plan.info.engineerCompany = QStringLiteral("Kaohsiung Automation");
    plan.info.witness = QStringLiteral("Lin Mei");
    plan.info.witnessCompany = QStringLiteral("TUV Taiwan");
    plan.info.customerSignatory = QStringLiteral("J. Smith");
    const QDateTime start(QDate(2026, 12, 7), QTime(1, 0), Qt::UTC);
    for (std::size_t i = 0; i < plan.points.size(); ++i) {
        CheckoutPoint &p = plan.points[i];
        const QString a = QString::fromStdString(p.address.toString());
        p.name = QStringLiteral("TAG_") + a;
        if (i >= 90)
            continue; // untested
        p.result = (i == 10 || i == 50) ? CheckoutResult::Failed : CheckoutResult::Passed;
        p.time = start.addSecs(static_cast<qint64>(i) * 60);
        p.engineer = i < 84 ? QStringLiteral("Chen") : QStringLiteral("Lee");
        if (i % 7 == 3)
            p.comment = QStringLiteral("begin_%1 %2 end_%1").arg(a, longComment);
    }
    // X30 deferred (its reason and owner on the punch list); X5 failed first, mended, re-tested
    // and closed out.
    CheckoutPoint &x30 = plan.points[30];
    x30.result = CheckoutResult::Deferred;
    x30.comment = QStringLiteral("panel_not_powered");
    x30.punch.owner = QStringLiteral("Wang");
    CheckoutPoint &x5 = plan.points[5];
    CheckoutAttempt first = x5.attempt();
    first.result = CheckoutResult::Failed;
    first.comment = QStringLiteral("wire_loose");
    first.time = x5.time.addSecs(-3600);
    x5.earlier.push_back(first);
    x5.punch.owner = QStringLiteral("Wang");
    x5.punch.closed = x5.time.addSecs(60);
    x5.punch.closedBy = QStringLiteral("Chen");
    return plan;
}

// The page of the first word `text` on pages [from, ...), -1 when none.
int pageOf(const std::vector<PdfText::Page> &pages, const QString &text, int from = 0)
{
    for (int p = from; p < static_cast<int>(pages.size()); ++p) {
        for (const PdfText::Word &w : pages[static_cast<std::size_t>(p)]) {
            if (w.text == text)
                return p;
        }
    }
    return -1;
}

// Whether words `a` and `b` stand side by side on `page` (the same table row's first line).
bool onOneLine(const PdfText::Page &page, const QString &a, const QString &b)
{
    for (const PdfText::Word &x : page) {
        for (const PdfText::Word &y : page) {
            if (x.text == a && y.text == b && qAbs(x.top - y.top) < 2)
                return true;
        }
    }
    return false;
}

// A page's text with every space removed (CJK words come out one character at a time).
QString squeezed(const PdfText::Page &page)
{
    return PdfText::pageText(page).remove(QLatin1Char(' '));
}

} // namespace

class TestCheckoutReport : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void englishReportHoldsTogether();
    void chineseReportHoldsTogether();
    void timesCarryTheirOffset();
    void engineerIsWhoRecordedMost();
    void pluralsInEveryLanguagePath();

private:
    // Renders, checks the pages common to both languages, returns them.
    std::vector<PdfText::Page> checkedPages(const CheckoutPlan &plan,
                                            const CheckoutReport::TextFunction &text,
                                            const QString &name, const QString &pageWord);

    QTemporaryDir m_dir;
};

void TestCheckoutReport::initTestCase()
{
    // Taipei's offset without depending on the tz database (POSIX: 8 h east of UTC).
    qputenv("TZ", "CST-8");
    tzset();
    QVERIFY(m_dir.isValid());
}

std::vector<PdfText::Page>
TestCheckoutReport::checkedPages(const CheckoutPlan &plan, const CheckoutReport::TextFunction &text,
                                 const QString &name, const QString &pageFormat)
{
    const CheckoutReport report = CheckoutReport::of(plan);
    const QString pdf = m_dir.filePath(name + QStringLiteral(".pdf"));
    if (!CheckoutPdf::write(report, pdf, text).ok())
        return {};
    // The pages as pictures too, for a person to look at (kept with the test's output).
    const QString ppm = QStandardPaths::findExecutable(QStringLiteral("pdftoppm"));
    if (!ppm.isEmpty()) {
        const QString out = QDir::temp().filePath(QStringLiteral("fatek-report-") + name);
        QProcess::execute(
            ppm, {QStringLiteral("-r"), QStringLiteral("60"), QStringLiteral("-png"), pdf, out});
    }
    const std::vector<PdfText::Page> pages = PdfText::pages(pdf);
    const int count = static_cast<int>(pages.size());
    if (count < 4) {
        qWarning("%s: %d pages: %s", qPrintable(name), count, qPrintable(PdfText::plain(pdf)));
        return {};
    }
    for (int p = 0; p < count; ++p) {
        const QString page = squeezed(pages[static_cast<std::size_t>(p)]);
        // Page N of M, the project, the customer and the document on every page.
        const QString number = pageFormat.arg(p + 1).arg(count).remove(QLatin1Char(' '));
        if (!page.contains(number) || !page.contains(QStringLiteral("Line7packer"))
            || !page.contains(QStringLiteral("ACMEFoods"))
            || !page.contains(QStringLiteral("SAT-0427"))) {
            qWarning("%s page %d lacks \"%s\", the project, the customer or the document: %s",
                     qPrintable(name), p + 1, qPrintable(number), qPrintable(page));
            return {};
        }
    }
    return pages;
}

void TestCheckoutReport::englishReportHoldsTogether()
{
    const CheckoutPlan plan = plan96(
        QStringLiteral("the sensor was found loose on its bracket, tightened, re-tested three "
                       "times from the panel and from the field, wiring ferrule replaced, "
                       "label missing and written by hand, to be printed before handover"));
    const std::vector<PdfText::Page> pages
        = checkedPages(plan, {}, QStringLiteral("en"), QStringLiteral("Page %1 of %2"));
    QVERIFY(!pages.empty());

    // Page 1 is the summary: the failed points and those not tested, no result table.
    const QString first = PdfText::pageText(pages[0]);
    QVERIFY2(first.contains(QLatin1String("96 points: 87 passed, 0 passed with remark, 2 failed, 1 "
                                          "deferred, 0 not applicable, 6 untested.")),
             qPrintable(first));
    QVERIFY2(first.contains(QLatin1String("Punch list")), qPrintable(first));
    // The punch list: the deferred point with its reason and owner, open; the mended one with the
    // old failure, closed; the failed ones open.
    QVERIFY2(onOneLine(pages[0], QStringLiteral("X30"), QStringLiteral("panel_not_powered")),
             qPrintable(first));
    QVERIFY2(onOneLine(pages[0], QStringLiteral("X30"), QStringLiteral("Wang")), qPrintable(first));
    QVERIFY2(onOneLine(pages[0], QStringLiteral("X5"), QStringLiteral("wire_loose")),
             qPrintable(first));
    QVERIFY2(onOneLine(pages[0], QStringLiteral("X5"), QStringLiteral("closed")),
             qPrintable(first));
    QVERIFY2(onOneLine(pages[0], QStringLiteral("X10"), QStringLiteral("open")), qPrintable(first));
    QVERIFY2(first.contains(QLatin1String("Not tested (6): R110, R111, R112, R113, R114, R115")),
             qPrintable(first));
    QVERIFY2(pageOf(pages, QStringLiteral("Results")) >= 1, qPrintable(first));

    // Every page of rows starts with the column header; every point's row is on exactly one page,
    // whole (both markers of a wrapped comment on the page of its address).
    const int firstRows = pageOf(pages, QStringLiteral("Results"));
    for (int p = firstRows; p < static_cast<int>(pages.size()); ++p) {
        const QString page = PdfText::pageText(pages[static_cast<std::size_t>(p)]);
        for (const char *column : {"Point", "Name", "Group", "Kind", "Result", "Measured",
                                   "Comment", "Tested at", "Engineer", "Attempts"})
            QVERIFY2(page.contains(QLatin1String(column)),
                     qPrintable(QStringLiteral("page %1 has no column \"%2\": %3")
                                    .arg(p + 1)
                                    .arg(QLatin1String(column), page)));
    }
    int splitRowsChecked = 0;
    for (const CheckoutPoint &point : plan.points) {
        const QString a = QString::fromStdString(point.address.toString());
        const int at = pageOf(pages, a, firstRows);
        QVERIFY2(at >= firstRows, qPrintable(a + QStringLiteral(" has no row")));
        QVERIFY2(pageOf(pages, a, at + 1) == -1, qPrintable(a + QStringLiteral(" twice")));
        if (!point.comment.startsWith(QLatin1String("begin_")))
            continue;
        QVERIFY2(pageOf(pages, QStringLiteral("begin_") + a, firstRows) == at,
                 qPrintable(QStringLiteral("begin_") + a));
        QVERIFY2(pageOf(pages, QStringLiteral("end_") + a, firstRows) == at,
                 qPrintable(QStringLiteral("end_") + a));
        ++splitRowsChecked;
    }
    QCOMPARE(splitRowsChecked, 13);

    // The signatures close the last page, with the last row above them, and the engineer's name.
    const int last = static_cast<int>(pages.size()) - 1;
    const QString lastPage = PdfText::pageText(pages.back());
    QCOMPARE(pageOf(pages, QStringLiteral("Witness")), last);
    QCOMPARE(pageOf(pages, QStringLiteral("R115"), firstRows), last);
    QVERIFY2(onOneLine(pages.back(), QStringLiteral("Commissioning"), QStringLiteral("Chen")),
             qPrintable(lastPage));
    QVERIFY2(onOneLine(pages.back(), QStringLiteral("Customer"), QStringLiteral("ACME")),
             qPrintable(lastPage));
    // Printed names and companies of all three signatories.
    QVERIFY2(onOneLine(pages.back(), QStringLiteral("Witness"), QStringLiteral("TUV")),
             qPrintable(lastPage));
    QVERIFY2(onOneLine(pages.back(), QStringLiteral("Witness"), QStringLiteral("Mei")),
             qPrintable(lastPage));
    QVERIFY2(onOneLine(pages.back(), QStringLiteral("Customer"), QStringLiteral("Smith")),
             qPrintable(lastPage));
    QVERIFY2(onOneLine(pages.back(), QStringLiteral("Commissioning"), QStringLiteral("Kaohsiung")),
             qPrintable(lastPage));
    // X5's row says it took two attempts.
    const int x5 = pageOf(pages, QStringLiteral("X5"), firstRows);
    QVERIFY2(
        onOneLine(pages[static_cast<std::size_t>(x5)], QStringLiteral("X5"), QStringLiteral("2")),
        qPrintable(PdfText::pageText(pages[static_cast<std::size_t>(x5)])));
}

void TestCheckoutReport::chineseReportHoldsTogether()
{
    ReportTranslator chinese;
    QVERIFY(chinese.setLanguage(QStringLiteral("zh_TW")));
    const CheckoutPlan plan = plan96(QStringLiteral(
        "感測器支架鬆動，已鎖緊並由盤面與現場各重測三次；端子套管更換，容許誤差 50，標籤遺失"
        "已手寫，移交前須列印標籤並由客戶確認"));
    const std::vector<PdfText::Page> pages = checkedPages(
        plan, [&chinese](const Message &m) { return chinese.text(m); }, QStringLiteral("zh_TW"),
        chinese.text(msg<MsgId::ReportPageOf>(1, 2))
            .replace(QLatin1Char('1'), QStringLiteral("%1"))
            .replace(QLatin1Char('2'), QStringLiteral("%2")));
    QVERIFY(!pages.empty());
    const int firstRows = pageOf(pages, QStringLiteral("X0"));
    QVERIFY(firstRows >= 1);
    const QString header = chinese.text(msg<MsgId::ReportTested>());
    for (int p = firstRows; p < static_cast<int>(pages.size()); ++p)
        QVERIFY2(squeezed(pages[static_cast<std::size_t>(p)]).contains(header),
                 qPrintable(QStringLiteral("page %1 has no column header").arg(p + 1)));
    for (const CheckoutPoint &point : plan.points) {
        if (!point.comment.startsWith(QLatin1String("begin_")))
            continue;
        const QString a = QString::fromStdString(point.address.toString());
        const int at = pageOf(pages, a, firstRows);
        QVERIFY2(pageOf(pages, QStringLiteral("begin_") + a, firstRows) == at,
                 qPrintable(QStringLiteral("begin_") + a));
        QVERIFY2(pageOf(pages, QStringLiteral("end_") + a, firstRows) == at,
                 qPrintable(QStringLiteral("end_") + a));
    }
    QCOMPARE(pageOf(pages, QStringLiteral("R115"), firstRows), static_cast<int>(pages.size()) - 1);
    QVERIFY(squeezed(pages.back()).contains(chinese.text(msg<MsgId::ReportSignWitness>())));
    // The punch list in Chinese on the summary page, its words whole.
    const QString first = squeezed(pages[0]);
    for (const Message &m :
         {msg<MsgId::ReportPunchList>(), msg<MsgId::ReportOwner>(), msg<MsgId::ReportPunchOpen>(),
          checkoutResultMessage(CheckoutResult::Deferred)}) {
        const QString word = chinese.text(m);
        QVERIFY2(word != QString::fromStdString(english(m)), qPrintable(word));
        QVERIFY2(first.contains(word), qPrintable(word + QStringLiteral(" not in: ") + first));
    }
}

void TestCheckoutReport::timesCarryTheirOffset()
{
    const CheckoutReport report = CheckoutReport::of(
        plan96(QStringLiteral("x")), QDateTime(QDate(2026, 12, 8), QTime(2, 30), Qt::UTC));
    QCOMPARE(report.rows[0].time, QStringLiteral("2026-12-07 09:00:00 +08:00"));
    QCOMPARE(report.made, QStringLiteral("2026-12-08 10:30:00 +08:00"));
    const auto field = [&report](MessageId id) {
        for (const CheckoutReport::Field &f : report.fields) {
            if (f.label.id == id)
                return englishText(f.value);
        }
        return QString();
    };
    QCOMPARE(field(MsgId::ReportTestDates),
             QStringLiteral("2026-12-07 09:00:00 +08:00 to 2026-12-07 10:29:00 +08:00"));
    // Not a "Date" the report was made passed off as the test date.
    QCOMPARE(field(MsgId::ReportDate), QString());
    QCOMPARE(CheckoutReport::timeText(QDateTime(QDate(2026, 1, 1), QTime(0, 0), Qt::UTC)),
             QStringLiteral("2026-01-01 08:00:00 +08:00"));
}

void TestCheckoutReport::engineerIsWhoRecordedMost()
{
    CheckoutPlan plan = plan96(QStringLiteral("x"));
    plan.points[3].engineer.clear();
    const CheckoutReport report = CheckoutReport::of(plan);
    QString engineers;
    for (const CheckoutReport::Field &f : report.fields) {
        if (f.label.id == MsgId::ReportEngineer)
            engineers = englishText(f.value);
    }
    QCOMPARE(engineers, QStringLiteral("Chen (83 points); Lee (6 points); not named (1 point)"));
    QCOMPARE(report.engineer, QStringLiteral("Chen"));
    // Nothing recorded yet: the plan's engineer signs.
    const CheckoutReport empty
        = CheckoutReport::of(CheckoutPlan::fromRanges(QStringLiteral("X0")).value());
    QCOMPARE(empty.engineer, QString());
}

void TestCheckoutReport::pluralsInEveryLanguagePath()
{
    // fatek-cli prints its English report through ReportTranslator, not the UI's translator.
    ReportTranslator english;
    QVERIFY(english.setLanguage(QStringLiteral("en")));
    QCOMPARE(english.text(msg<MsgId::ReportSummary>(18, 12, 1, 4, 0, 0, 1)),
             QStringLiteral("18 points: 12 passed, 1 passed with remark, 4 failed, 0 deferred, 0 "
                            "not applicable, 1 untested."));
    QCOMPARE(english.text(msg<MsgId::ReportSummary>(1, 1, 0, 0, 0, 0, 0)),
             QStringLiteral("1 point: 1 passed, 0 passed with remark, 0 failed, 0 deferred, 0 not "
                            "applicable, 0 untested."));
    ReportTranslator chinese;
    QVERIFY(chinese.setLanguage(QStringLiteral("zh_TW")));
    QVERIFY(
        !chinese.text(msg<MsgId::ReportSummary>(18, 12, 1, 4, 0, 0, 1)).contains(QLatin1Char('{')));
    QCOMPARE(english.text(msg<MsgId::ReportEngineerPoints>("Chen", 1)),
             QStringLiteral("Chen (1 point)"));
}

QTEST_MAIN(TestCheckoutReport)
#include "tst_checkoutreport.moc"
