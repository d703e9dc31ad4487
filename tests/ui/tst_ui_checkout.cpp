// Tools -> I/O Checkout (issue 36) as a commissioning engineer uses it on a 1366x768 laptop: the
// real main window connected to a simulated FBs over loopback TCP (STOP, no demo ladder: only the
// test moves the inputs, as the technician's hand in the field), the tool opened from the Tools
// menu, the plan typed, five points walked by keyboard. What was forced is checked in the
// simulator's own memory. With FATEK_CHECKOUT_SHOTS set to a folder, the tool's picture and the
// PDF report are written there (docs/images/tool-checkout.png, checkout-report.png).
#include "checkoutbench.h"
#include "core/commission/checkoutfile.h"
#include "core/sim/faultconfig.h"
#include "testutil.h"
#include "uitestutil.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QScreen>
#include <QTableView>

#include <functional>

using namespace Fatek;
using namespace CheckoutBench;

class TestUiCheckout : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;
    Bench m_bench;
    QTemporaryDir &m_files = m_bench.files;
    SimulatedPlc *m_plc = nullptr;
    SimServer *m_server = nullptr;

    void actuate(IoCheckoutDialog *dialog, const char *input)
    {
        QVERIFY(m_bench.actuate(dialog, input));
        QCOMPARE(state(dialog, dialog->runner()->plan().indexOf(addr(input))),
                 resultText(CheckoutResult::Passed));
    }
    bool openWindow(bool operatorMode) { return m_bench.openWindow(operatorMode); }
    IoCheckoutDialog *openFromToolsMenu() { return m_bench.openFromToolsMenu(); }
    bool startPlan(IoCheckoutDialog *dialog, const QString &ranges, const QString &fileName)
    {
        return m_bench.startPlan(dialog, ranges, fileName);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        QVERIFY(m_files.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_checkout"));
        QCOMPARE(QGuiApplication::primaryScreen()->size(), laptop);
    }

    void init()
    {
        // STOP, no demo ladder: the inputs move only when the test moves them.
        QString error;
        QVERIFY2(m_bench.init(&error), qPrintable(error));
        m_plc = m_bench.plc.get();
        m_server = m_bench.server.get();
    }

    void cleanup() { m_bench.cleanup(); }

    void walkFivePointsByKeyboard()
    {
        QVERIFY(openWindow(false));
        IoCheckoutDialog *dialog = openFromToolsMenu();
        QVERIFY(dialog);
        QVERIFY(QTest::qWaitForWindowExposed(dialog));
        // The file dialogs answered by the test; the questions come as real message boxes.
        const QString file = m_files.filePath(QStringLiteral("line3.checkout.json"));
        QString chosen = file;
        dialog->setFileChooser([&chosen](const ToolDialogFrame::FileQuestion &) { return chosen; });
        // On the laptop's screen, whole.
        QVERIFY2(
            QGuiApplication::primaryScreen()->availableGeometry().contains(dialog->frameGeometry()),
            qPrintable(QStringLiteral("%1x%2").arg(dialog->width()).arg(dialog->height())));

        // The plan, typed.
        const auto type = [dialog](const char *field, const QString &text) {
            auto *edit = dialog->findChild<QLineEdit *>(QLatin1String(field));
            QVERIFY(edit);
            QTest::mouseClick(edit, Qt::LeftButton);
            QTest::keyClicks(edit, text, {}, keyDelayMs);
        };
        type("ranges", QStringLiteral("X0..X2, Y0..Y1, X3..X7, Y2..Y3, R100"));
        type("project", QStringLiteral("Line 3"));
        type("customer", QStringLiteral("ACME Foods"));
        type("engineer", QStringLiteral("Lin"));
        auto *start = dialog->findChild<QPushButton *>(QStringLiteral("startButton"));
        QVERIFY(start && start->isEnabled());
        QTest::mouseClick(start, Qt::LeftButton);
        CheckoutRunner *runner = dialog->runner();
        QTRY_VERIFY_WITH_TIMEOUT(runner->isRunning(), longWait);
        QCOMPARE(dialog->points()->rowCount(), 13);
        QTableView *table = dialog->table();
        QTRY_VERIFY_WITH_TIMEOUT(runner->isStarted() && runner->currentPoint() == 0, longWait);
        QTRY_COMPARE_WITH_TIMEOUT(table->currentIndex().row(), 0, longWait);
        // The first poll shows each input's value: the baseline.
        QTRY_VERIFY_WITH_TIMEOUT(dialog->points()
                                     ->index(2, CheckoutTableModel::MeasuredColumn)
                                     .data()
                                     .toString()
                                     .contains(QLatin1String("0")),
                                 longWait);

        // X0 and X1 actuated in the field: passed, the tool moves on by itself.
        actuate(dialog, "X0");
        QVERIFY(!QTest::currentTestFailed());
        QTRY_COMPARE_WITH_TIMEOUT(runner->currentPoint(), 1, longWait);
        actuate(dialog, "X1");
        QVERIFY(!QTest::currentTestFailed());
        QTRY_COMPARE_WITH_TIMEOUT(runner->currentPoint(), 2, longWait);
        QCOMPARE(table->currentIndex().row(), 2);
        // X2 does not answer: F, then N to the next point, the output Y0.
        QTest::keyClick(table, Qt::Key_F, {}, keyDelayMs);
        QTRY_COMPARE_WITH_TIMEOUT(state(dialog, 2), resultText(CheckoutResult::Failed), longWait);
        QTest::keyClick(table, Qt::Key_N, {}, keyDelayMs);
        QTRY_COMPARE_WITH_TIMEOUT(runner->currentPoint(), 3, longWait);
        QTRY_COMPARE_WITH_TIMEOUT(table->currentIndex().row(), 3, longWait);

        // Y0: Space asks, the output is forced on in the PLC (disabled and set).
        const QString question = UiTestUtil::answerModal(
            [table] { QTest::keyClick(table, Qt::Key_Space, {}, keyDelayMs); }, clickYes);
        QVERIFY2(question.contains(QLatin1String("Y0")), qPrintable(question));
        QTRY_COMPARE_WITH_TIMEOUT(runner->outputUnderTest(), 3, longWait);
        // The table says so once it is forced.
        QTRY_COMPARE_WITH_TIMEOUT(state(dialog, 3), CheckoutTableModel::tr("forced: seen?"),
                                  longWait);
        QTRY_VERIFY_WITH_TIMEOUT(
            m_plc->isDisabled(addr("Y0")) == true && m_plc->value(addr("Y0")) == 1u, longWait);
        // Seen in the field: Space; released at once (enabled and reset).
        QTest::keyClick(table, Qt::Key_Space, {}, keyDelayMs);
        QTRY_COMPARE_WITH_TIMEOUT(state(dialog, 3), resultText(CheckoutResult::Passed), longWait);
        QTRY_VERIFY_WITH_TIMEOUT(
            m_plc->isDisabled(addr("Y0")) == false && m_plc->value(addr("Y0")) == 0u, longWait);

        // Y1: N, Space (forced), F: not seen in the field, failed and released.
        QTest::keyClick(table, Qt::Key_N, {}, keyDelayMs);
        QTRY_COMPARE_WITH_TIMEOUT(runner->currentPoint(), 4, longWait);
        UiTestUtil::answerModal([table] { QTest::keyClick(table, Qt::Key_Space, {}, keyDelayMs); },
                                clickYes);
        QTRY_VERIFY_WITH_TIMEOUT(
            m_plc->isDisabled(addr("Y1")) == true && m_plc->value(addr("Y1")) == 1u, longWait);
        QTest::keyClick(table, Qt::Key_F, {}, keyDelayMs);
        QTRY_COMPARE_WITH_TIMEOUT(state(dialog, 4), resultText(CheckoutResult::Failed), longWait);
        QTRY_VERIFY_WITH_TIMEOUT(
            m_plc->isDisabled(addr("Y1")) == false && m_plc->value(addr("Y1")) == 0u, longWait);

        // The table says it all.
        const QStringList expected
            = {resultText(CheckoutResult::Passed), resultText(CheckoutResult::Passed),
               resultText(CheckoutResult::Failed), resultText(CheckoutResult::Passed),
               resultText(CheckoutResult::Failed)};
        for (int row = 0; row < 5; ++row)
            QCOMPARE(state(dialog, row), expected.at(row));
        QTRY_VERIFY_WITH_TIMEOUT(!runner->hasForced(), longWait); // the release confirmed

        // A comment on the failed input, typed into the table (F2 edits it).
        const QModelIndex comment = dialog->points()->index(2, CheckoutTableModel::CommentColumn);
        table->setCurrentIndex(comment);
        QTest::keyClick(table, Qt::Key_F2, {}, keyDelayMs);
        QLineEdit *editor = nullptr;
        QTRY_VERIFY_WITH_TIMEOUT((editor = table->viewport()->findChild<QLineEdit *>())
                                     && editor->isVisible(),
                                 longWait);
        QTest::keyClicks(editor, QStringLiteral("no wire at X2"), {}, keyDelayMs);
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE_WITH_TIMEOUT(comment.data().toString(), QStringLiteral("no wire at X2"),
                                  longWait);
        QCOMPARE(runner->plan().points[2].comment, QStringLiteral("no wire at X2"));

        const QString shots = qEnvironmentVariable("FATEK_CHECKOUT_SHOTS");
        if (!shots.isEmpty()) {
            table->setCurrentIndex(dialog->points()->index(2, 0));
            QTest::qWait(300);
            QVERIFY(dialog->grab().save(QDir(shots).filePath(QStringLiteral("tool-checkout.png"))));
        }

        // Saved as it went: the file has every result and nothing forced.
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(file), longWait);
        const auto loaded = CheckoutFile::loadFromFile(file);
        QVERIFY(loaded.ok());
        QCOMPARE(loaded->points.size(), std::size_t(13));
        QCOMPARE(loaded->points[3].result, CheckoutResult::Passed);
        QCOMPARE(loaded->points[4].result, CheckoutResult::Failed);
        QVERIFY(loaded->forced.empty());
        QCOMPARE(loaded->info.customer, QStringLiteral("ACME Foods"));
        QTRY_COMPARE_WITH_TIMEOUT(CheckoutFile::loadFromFile(file)->points[2].comment,
                                  QStringLiteral("no wire at X2"), longWait);

        // The report, PDF and CSV, through the Report button.
        auto *report = dialog->findChild<QPushButton *>(QStringLiteral("reportButton"));
        QVERIFY(report && report->isEnabled());
        const QString pdf = m_files.filePath(QStringLiteral("line3.pdf"));
        chosen = pdf;
        QVERIFY(pickFromMenu(report, "reportPdfAction"));
        QFile pdfFile(pdf);
        QVERIFY(pdfFile.open(QIODevice::ReadOnly));
        QVERIFY(pdfFile.read(5).startsWith("%PDF"));
        const QString csv = m_files.filePath(QStringLiteral("line3.csv"));
        chosen = csv;
        QVERIFY(pickFromMenu(report, "reportCsvAction"));
        QFile csvFile(csv);
        QVERIFY(csvFile.open(QIODevice::ReadOnly));
        const QByteArray csvText = csvFile.readAll();
        QVERIFY2(csvText.contains("ACME Foods") && csvText.contains("Y1"), csvText.constData());
        if (!shots.isEmpty()) {
            QFile::remove(QDir(shots).filePath(QStringLiteral("checkout-report.pdf")));
            QVERIFY(QFile::copy(pdf, QDir(shots).filePath(QStringLiteral("checkout-report.pdf"))));
        }

        // Closed: nothing polls, nothing stays forced.
        dialog->reject();
        QTRY_VERIFY_WITH_TIMEOUT(!runner->isRunning(), longWait);
        QVERIFY(m_plc->isDisabled(addr("Y0")) == false);
        QVERIFY(m_plc->isDisabled(addr("Y1")) == false);
    }

    // A checkout that died with Y0 forced: opening its file offers to release it, and does.
    void openReleasesLeftovers()
    {
        m_plc->setDisabled(addr("Y0"), true);
        m_plc->setValue(addr("Y0"), 1);
        auto plan = CheckoutPlan::fromRanges(QStringLiteral("X0, Y0"));
        QVERIFY(plan.ok());
        CheckoutPlan left = plan.value();
        left.forced.push_back(addr("Y0"));
        const QString file = m_files.filePath(QStringLiteral("left.checkout.json"));
        QVERIFY(CheckoutFile::saveToFile(left, file).ok());

        QVERIFY(openWindow(false));
        IoCheckoutDialog *dialog = openFromToolsMenu();
        QVERIFY(dialog);
        QStringList questions;
        answerYes(dialog, questions);
        QVERIFY(dialog->openCheckout(file));
        QCOMPARE(questions.size(), 1);
        QVERIFY2(questions.front().contains(QLatin1String("Y0")), qPrintable(questions.front()));
        QTRY_VERIFY_WITH_TIMEOUT(
            m_plc->isDisabled(addr("Y0")) == false && m_plc->value(addr("Y0")) == 0u, longWait);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->runner()->hasForced(), longWait);
        QTRY_VERIFY_WITH_TIMEOUT(CheckoutFile::loadFromFile(file)->forced.empty(), longWait);
        QVERIFY(dialog->runner()->isRunning());
    }

    // Operator mode: the inputs are watched, an output is refused before anything is asked or
    // written.
    void operatorModeRefusesOutputs()
    {
        QVERIFY(openWindow(true));
        IoCheckoutDialog *dialog = openFromToolsMenu();
        QVERIFY(dialog);
        QStringList questions;
        answerYes(dialog, questions);
        QVERIFY(
            startPlan(dialog, QStringLiteral("X0, Y0"), QStringLiteral("operator.checkout.json")));
        CheckoutRunner *runner = dialog->runner();
        QTRY_VERIFY_WITH_TIMEOUT(runner->isRunning(), longWait);
        QTRY_VERIFY_WITH_TIMEOUT(runner->isStarted() && runner->currentPoint() == 0, longWait);
        actuate(dialog, "X0");
        if (QTest::currentTestFailed())
            return;
        QTest::keyClick(dialog->table(), Qt::Key_N, {}, keyDelayMs);
        QTRY_COMPARE_WITH_TIMEOUT(runner->currentPoint(), 1, longWait);
        QTest::keyClick(dialog->table(), Qt::Key_Space, {}, keyDelayMs);
        QCOMPARE(dialog->messageText(),
                 IoCheckoutDialog::tr("Operator mode: outputs are not forced."));
        QVERIFY(questions.isEmpty());
        QCOMPARE(runner->outputUnderTest(), -1);
        QVERIFY(m_plc->isDisabled(addr("Y0")) == false);
        QCOMPARE(state(dialog, 1), resultText(CheckoutResult::Untested));
    }

    // Y0 answered while the PLC's answers are lost (the simulator executes every request and
    // withholds its answer): the release is said to have failed, is tried again, and once the
    // answers come back the PLC has Y0 released and the file no longer lists it (issue 48,
    // case 2; tst_checkout_release stops a fatek-sim child instead).
    void releaseRetriedUntilConfirmed()
    {
        QVERIFY(openWindow(false));
        IoCheckoutDialog *dialog = openFromToolsMenu();
        QVERIFY(dialog);
        dialog->setConfirmer([](const QString &) { return true; });
        QVERIFY(startPlan(dialog, QStringLiteral("Y0..Y1"), QStringLiteral("retry.checkout.json")));
        const QString file = m_files.filePath(QStringLiteral("retry.checkout.json"));
        CheckoutRunner *runner = dialog->runner();
        QTRY_VERIFY_WITH_TIMEOUT(runner->isStarted() && runner->currentPoint() == 0, longWait);
        QTest::keyClick(dialog->table(), Qt::Key_Space, {}, keyDelayMs);
        QTRY_COMPARE_WITH_TIMEOUT(state(dialog, 0), CheckoutTableModel::tr("forced: seen?"),
                                  longWait);

        FaultConfig lost;
        lost.dropRate = 1.0;
        m_server->setFaults(lost);
        QTest::keyClick(dialog->table(), Qt::Key_Space, {}, keyDelayMs);
        QTRY_VERIFY_WITH_TIMEOUT(dialog->messageText().startsWith(QLatin1String("Releasing Y0 "
                                                                                "failed")),
                                 longWait);
        QVERIFY(runner->isRetryingRelease());
        QCOMPARE(CheckoutFile::loadFromFile(file)->forced, std::vector<Address>{addr("Y0")});
        auto *newButton = dialog->findChild<QPushButton *>(QStringLiteral("newButton"));
        QVERIFY(newButton && !newButton->isEnabled());

        m_server->setFaults({});
        QTRY_VERIFY_WITH_TIMEOUT(!runner->hasForced(), longWait);
        QCOMPARE(m_plc->isDisabled(addr("Y0")), std::optional<bool>(false));
        QCOMPARE(m_plc->value(addr("Y0")), std::optional<std::uint32_t>(0));
        QVERIFY(CheckoutFile::loadFromFile(file)->forced.empty());
        QCOMPARE(state(dialog, 0), resultText(CheckoutResult::Passed));
    }

    // The PLC in RUN and the plan "Y0" started; Space on Y0. Every question is answered by
    // `answer` (its number from 0) and recorded with the message the tool showed meanwhile.
    IoCheckoutDialog *spaceOnY0InRun(QStringList &questions, QStringList &shown,
                                     std::function<bool(int)> answer)
    {
        m_plc->setRunning(true);
        if (!openWindow(false))
            return nullptr;
        IoCheckoutDialog *dialog = openFromToolsMenu();
        if (!dialog)
            return nullptr;
        dialog->setConfirmer([&questions, &shown, dialog, answer](const QString &question) {
            questions << question;
            shown << dialog->messageText();
            return answer(int(questions.size()) - 1);
        });
        if (!startPlan(dialog, QStringLiteral("Y0"), QStringLiteral("run.checkout.json")))
            return nullptr;
        CheckoutRunner *runner = dialog->runner();
        // Every point read once (the tool says "Watching the inputs"): a force before that is
        // refused.
        if (!QTest::qWaitFor(
                [runner] { return runner->isStarted() && runner->currentPoint() == 0; }, longWait))
            return nullptr;
        QTest::keyClick(dialog->table(), Qt::Key_Space, {}, keyDelayMs);
        return dialog;
    }

    // The PLC in RUN: after the force is confirmed, the tool asks once more (the machine runs),
    // says what each answer does, and forces only then; while it asks, nothing claims that
    // nothing was forced (issue 48, case 3).
    void plcInRunAsksAgain()
    {
        QStringList questions;
        QStringList shown;
        IoCheckoutDialog *dialog = spaceOnY0InRun(questions, shown, [](int) { return true; });
        QVERIFY(dialog);
        QTRY_COMPARE_WITH_TIMEOUT(questions.size(), 2, longWait);
        QCOMPARE(questions.at(1), translated(msg<MsgId::CheckoutPlcInRun>(std::string("Y0"))));
        QVERIFY2(!shown.at(1).contains(QLatin1String("nothing was forced")),
                 qPrintable(shown.at(1)));
        QVERIFY2(!shown.at(1).contains(QLatin1String("not confirmed")), qPrintable(shown.at(1)));
        QTRY_VERIFY_WITH_TIMEOUT(
            m_plc->isDisabled(addr("Y0")) == true && m_plc->value(addr("Y0")) == 1u, longWait);
        QTRY_COMPARE_WITH_TIMEOUT(state(dialog, 0), CheckoutTableModel::tr("forced: seen?"),
                                  longWait);
        QVERIFY2(!dialog->messageText().contains(QLatin1String("nothing was forced")),
                 qPrintable(dialog->messageText()));
        QTest::keyClick(dialog->table(), Qt::Key_Space, {}, keyDelayMs);
        QTRY_COMPARE_WITH_TIMEOUT(state(dialog, 0), resultText(CheckoutResult::Passed), longWait);
        QTRY_VERIFY_WITH_TIMEOUT(
            m_plc->isDisabled(addr("Y0")) == false && m_plc->value(addr("Y0")) == 0u, longWait);
    }

    // No to the RUN question: nothing is forced, the output stays untested, and the tool says so.
    void plcInRunNoForcesNothing()
    {
        QStringList questions;
        QStringList shown;
        IoCheckoutDialog *dialog
            = spaceOnY0InRun(questions, shown, [](int question) { return question == 0; });
        QVERIFY(dialog);
        QTRY_COMPARE_WITH_TIMEOUT(questions.size(), 2, longWait);
        QTRY_COMPARE_WITH_TIMEOUT(dialog->messageText(),
                                  translated(msg<MsgId::CheckoutRunNotConfirmed>()), longWait);
        QCOMPARE(dialog->runner()->outputUnderTest(), -1);
        QVERIFY(!dialog->runner()->hasForced());
        QCOMPARE(state(dialog, 0), resultText(CheckoutResult::Untested));
        QCOMPARE(m_plc->isDisabled(addr("Y0")), std::optional<bool>(false));
    }
};

// A screen of a laptop's size: the offscreen platform reads it from a configuration file.
int main(int argc, char *argv[])
{
    const UiTestUtil::OffscreenScreen screen(laptop);
    if (!screen.isReady())
        return 1;
    QApplication app(argc, argv);
    TestUiCheckout test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_ui_checkout.moc"
