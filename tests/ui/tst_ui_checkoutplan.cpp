// Tools -> I/O Checkout as loop-check sheets keep it (issue 53), on a 1366x768 laptop: every
// status set by its key on the real table, re-tests that keep the history, crossed wiring that
// cannot pass clean, analog points read at the checks of their scale, plans imported from a CSV
// or the main window's names, F2 on any cell, the report's details, the punch list and its CSV,
// and closing (the dialog or the main window) with an output forced: released, and the file says
// so. The PLC is the simulated FBs of CheckoutBench; what was forced is read in its memory.
#include "checkoutbench.h"
#include "core/commission/checkoutfile.h"
#include "core/sim/faultconfig.h"
#include "testutil.h"
#include "ui/common/csvfilefilter.h"
#include "ui/tools/checkoutpunchdialog.h"
#include "uitestutil.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QFile>
#include <QLabel>
#include <QScreen>
#include <QTableView>
#include <QTableWidget>

#include <optional>

using namespace Fatek;
using namespace CheckoutBench;

namespace {

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

QByteArray readFile(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestUiCheckoutPlan : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;
    Bench m_bench;
    // What the remark and reason questions are answered with, in turn (nothing: Cancel).
    QList<std::optional<QString>> m_answers;
    QStringList m_asked;

    // The main window, the tool from its menu, answers by the test; nullptr when it failed.
    IoCheckoutDialog *openTool()
    {
        if (!m_bench.openWindow(false))
            return nullptr;
        IoCheckoutDialog *dialog = m_bench.openFromToolsMenu();
        if (!dialog)
            return nullptr;
        dialog->setConfirmer([](const QString &) { return true; });
        dialog->setTextAsker([this](const QString &question, const QString &) {
            m_asked << question;
            return m_answers.isEmpty() ? std::optional<QString>() : m_answers.takeFirst();
        });
        return dialog;
    }
    static void key(IoCheckoutDialog *dialog, Qt::Key k, Qt::KeyboardModifiers mods = {})
    {
        QTest::keyClick(dialog->table(), k, mods, keyDelayMs);
    }
    // The arrow keys to `row`, as a person moves the table's focus.
    static void goTo(IoCheckoutDialog *dialog, int row)
    {
        while (dialog->table()->currentIndex().row() < row)
            key(dialog, Qt::Key_Down);
        while (dialog->table()->currentIndex().row() > row)
            key(dialog, Qt::Key_Up);
    }
    // Started: the status read and the points probed, the inputs watched.
    static bool watching(IoCheckoutDialog *dialog)
    {
        return QTest::qWaitFor(
            [dialog] {
                return dialog->messageText().startsWith(
                    IoCheckoutDialog::tr("Watching the inputs: actuate %1 in the field.").left(20));
            },
            longWait);
    }
    // The plan "Y3" started and Y3 forced by Space (the force answered yes); its file's path, or
    // empty when it did not come so far.
    QString forceY3(IoCheckoutDialog *dialog, const QString &fileName)
    {
        const QString file = m_bench.files.filePath(fileName);
        if (!m_bench.startPlan(dialog, QStringLiteral("Y3"), fileName)
            || !QTest::qWaitFor(
                [dialog] {
                    return dialog->runner()->isStarted() && dialog->runner()->currentPoint() == 0;
                },
                longWait))
            return {};
        key(dialog, Qt::Key_Space);
        const bool forced = QTest::qWaitFor(
            [this] { return m_bench.plc->isDisabled(addr("Y3")) == true; }, longWait);
        return forced ? file : QString();
    }
    static QString cell(IoCheckoutDialog *dialog, int row, int column, int role = Qt::DisplayRole)
    {
        return dialog->points()->index(row, column).data(role).toString();
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        QVERIFY(m_bench.files.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_checkoutplan"));
        QCOMPARE(QGuiApplication::primaryScreen()->size(), laptop);
    }

    void init()
    {
        QString error;
        QVERIFY2(m_bench.init(&error), qPrintable(error));
        m_answers.clear();
        m_asked.clear();
    }

    void cleanup() { m_bench.cleanup(); }

    // R, D, A, F and T on the current row; each shown in the State column with its colour, the
    // attempt counted, the earlier one in the tooltip; T lets an input take new edges (items 1,
    // 2).
    void everyStatusByKey()
    {
        IoCheckoutDialog *dialog = openTool();
        QVERIFY(dialog);
        QVERIFY(m_bench.startPlan(dialog, QStringLiteral("X0..X3"),
                                  QStringLiteral("statuses.checkout.json")));
        CheckoutRunner *runner = dialog->runner();
        QVERIFY(watching(dialog));
        QTRY_COMPARE_WITH_TIMEOUT(dialog->table()->currentIndex().row(), 0, longWait);
        // The hint lists every key.
        auto *keys = dialog->findChild<QLabel *>(QStringLiteral("keys"));
        QVERIFY(keys);
        for (const char *k : {"Space", "F:", "R:", "D:", "A:", "T:", "N:", "V:", "Shift+V", "F2"})
            QVERIFY2(keys->text().contains(QLatin1String(k)), k);
        QCOMPARE(dialog->table()->toolTip(), keys->text());

        // R with no remark: refused in words, nothing recorded.
        m_answers = {QString()};
        key(dialog, Qt::Key_R);
        QCOMPARE(dialog->messageText(),
                 translated(msg<MsgId::CheckoutNeedsRemark>(std::string("X0"))));
        QCOMPARE(state(dialog, 0), resultText(CheckoutResult::Untested));
        // R with its remark.
        m_answers = {QStringLiteral("lamp dim, replace bulb")};
        key(dialog, Qt::Key_R);
        QCOMPARE(state(dialog, 0), resultText(CheckoutResult::PassedWithRemark));
        QCOMPARE(cell(dialog, 0, CheckoutTableModel::CommentColumn),
                 QStringLiteral("lamp dim, replace bulb"));
        // D on X1: the reason asked; cancelled, nothing; answered, deferred.
        goTo(dialog, 1);
        QTRY_COMPARE_WITH_TIMEOUT(runner->currentPoint(), 1, longWait);
        key(dialog, Qt::Key_D);
        QCOMPARE(state(dialog, 1), resultText(CheckoutResult::Untested));
        m_answers = {QStringLiteral("no cable yet")};
        key(dialog, Qt::Key_D);
        QCOMPARE(state(dialog, 1), resultText(CheckoutResult::Deferred));
        QVERIFY(m_asked.last().contains(QLatin1String("X1")));
        // A on X2, F on X3.
        goTo(dialog, 2);
        key(dialog, Qt::Key_A);
        QCOMPARE(state(dialog, 2), resultText(CheckoutResult::NotApplicable));
        goTo(dialog, 3);
        key(dialog, Qt::Key_F);
        QCOMPARE(state(dialog, 3), resultText(CheckoutResult::Failed));
        // Each status its own colour.
        QSet<QRgb> colours;
        for (int row = 0; row < 4; ++row)
            colours << dialog->points()
                           ->index(row, CheckoutTableModel::PointColumn)
                           .data(Qt::BackgroundRole)
                           .value<QColor>()
                           .rgb();
        QCOMPARE(colours.size(), 4);

        // T on the failed X3: tested again, its failure kept; it takes new edges and passes.
        key(dialog, Qt::Key_T);
        QVERIFY2(dialog->messageText().contains(QLatin1String("X3")),
                 qPrintable(dialog->messageText()));
        QCOMPARE(state(dialog, 3), CheckoutTableModel::tr("%1 (attempt %2)")
                                       .arg(resultText(CheckoutResult::Untested))
                                       .arg(2));
        QVERIFY(m_bench.actuate(dialog, "X3"));
        QCOMPARE(state(dialog, 3), CheckoutTableModel::tr("%1 (attempt %2)")
                                       .arg(resultText(CheckoutResult::Passed))
                                       .arg(2));
        const QString tip = cell(dialog, 3, CheckoutTableModel::StateColumn, Qt::ToolTipRole);
        QVERIFY2(tip.contains(CheckoutTableModel::tr("Attempt %1: %2, %3 by %4")
                                  .arg(1)
                                  .arg(resultText(CheckoutResult::Failed))
                                  .section(QLatin1Char(','), 0, 0)),
                 qPrintable(tip));
        QCOMPARE(runner->plan().points[3].attempts(), 2);
        // With FATEK_CHECKOUT_SHOTS set to a folder, its picture (docs/images).
        if (const QString shots = qEnvironmentVariable("FATEK_CHECKOUT_SHOTS"); !shots.isEmpty())
            QVERIFY(dialog->grab().save(shots + QStringLiteral("/tool-checkout-statuses.png")));
        // Saved as it went.
        const auto saved = CheckoutFile::loadFromFile(runner->filePath());
        QVERIFY(saved.ok());
        QCOMPARE(saved->points[1].result, CheckoutResult::Deferred);
        QCOMPARE(saved->points[1].comment, QStringLiteral("no cable yet"));
        QCOMPARE(saved->points[3].earlier.size(), std::size_t(1));
    }

    // X3 moves while X0 is under test: Space on X0 is refused, its edges fail it, Space stays
    // refused, R with a remark passes it (item 3).
    void crossedWiringCannotPassClean()
    {
        IoCheckoutDialog *dialog = openTool();
        QVERIFY(dialog);
        QVERIFY(m_bench.startPlan(dialog, QStringLiteral("X0, X3"),
                                  QStringLiteral("crossed.checkout.json")));
        CheckoutRunner *runner = dialog->runner();
        QTRY_VERIFY_WITH_TIMEOUT(runner->isStarted() && runner->currentPoint() == 0, longWait);
        QTRY_VERIFY_WITH_TIMEOUT(cell(dialog, 1, CheckoutTableModel::MeasuredColumn)
                                     .endsWith(CheckoutTableModel::tr("now %1").arg(0)),
                                 longWait);
        m_bench.plc->setValue(addr("X3"), 1);
        QTRY_VERIFY_WITH_TIMEOUT(!runner->plan().points[0].changedWith.empty(), longWait);
        m_bench.plc->setValue(addr("X3"), 0);
        QVERIFY(cell(dialog, 0, CheckoutTableModel::PointColumn, Qt::ToolTipRole)
                    .contains(QLatin1String("X3")));
        const QString refusal = translated(
            msg<MsgId::CheckoutCrossedCannotPass>(std::string("X0"), std::string("X3")));
        key(dialog, Qt::Key_Space);
        QCOMPARE(dialog->messageText(), refusal);
        QCOMPARE(state(dialog, 0), resultText(CheckoutResult::Untested));
        // Both edges of X0: failed, not passed.
        QVERIFY(m_bench.actuate(dialog, "X0"));
        QCOMPARE(state(dialog, 0), resultText(CheckoutResult::Failed));
        goTo(dialog, 0);
        QTRY_VERIFY_WITH_TIMEOUT(runner->isStarted() && runner->currentPoint() == 0, longWait);
        key(dialog, Qt::Key_Space);
        QCOMPARE(dialog->messageText(), refusal);
        QCOMPARE(state(dialog, 0), resultText(CheckoutResult::Failed));
        m_answers = {QStringLiteral("X0 and X3 swapped at the terminal, corrected")};
        key(dialog, Qt::Key_R);
        QCOMPARE(state(dialog, 0), CheckoutTableModel::tr("%1 (attempt %2)")
                                       .arg(resultText(CheckoutResult::PassedWithRemark))
                                       .arg(2));
    }

    // An analog point of a plan CSV read at its checks with V (the next check said in the
    // table), one off, adjusted and read again as left with Shift+V; a typed R200 without a
    // scale cannot pass, and the tool says how to give it one (items 4, 5).
    void analogChecksFromPlanCsv()
    {
        IoCheckoutDialog *dialog = openTool();
        QVERIFY(dialog);
        const QString csv = m_bench.files.filePath(QStringLiteral("plan.csv"));
        QVERIFY(writeFile(csv, "address,name,comment,group,low,high,tolerance,engLow,engHigh,"
                               "unit,checks\r\n"
                               "R100,PT1,Pressure,Tank,0,32000,0.1,4,20,mA,0/50/100\r\n"));
        QString chosen = csv;
        dialog->setFileChooser([&chosen](const ToolDialogFrame::FileQuestion &) { return chosen; });
        auto *import = dialog->findChild<QPushButton *>(QStringLiteral("importButton"));
        QVERIFY(pickFromMenu(import, "importCsvAction"));
        QCOMPARE(dialog->points()->rowCount(), 1);
        QCOMPARE(cell(dialog, 0, CheckoutTableModel::NameColumn), QStringLiteral("PT1"));
        chosen = m_bench.files.filePath(QStringLiteral("analog.checkout.json"));
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("startButton")),
                          Qt::LeftButton);
        CheckoutRunner *runner = dialog->runner();
        QTRY_VERIFY_WITH_TIMEOUT(runner->isStarted() && runner->currentPoint() == 0, longWait);
        const auto measured = [dialog] {
            return cell(dialog, 0, CheckoutTableModel::MeasuredColumn);
        };
        const CheckoutPoint &pt = runner->plan().points[0];
        QVERIFY2(measured().startsWith(CheckoutTableModel::tr("%1 %: %2 expected")
                                           .arg(QStringLiteral("0"), QStringLiteral("4.00 mA"))),
                 qPrintable(measured()));
        // 0 % and 50 % as expected.
        m_bench.plc->setValue(addr("R100"), 0);
        key(dialog, Qt::Key_V);
        QTRY_VERIFY_WITH_TIMEOUT(measured().contains(CheckoutTableModel::checkText(pt, 1)),
                                 longWait);
        QVERIFY2(dialog->messageText().contains(CheckoutTableModel::checkText(pt, 1)),
                 qPrintable(dialog->messageText()));
        m_bench.plc->setValue(addr("R100"), 16000);
        key(dialog, Qt::Key_V);
        QTRY_VERIFY_WITH_TIMEOUT(measured().contains(CheckoutTableModel::checkText(pt, 2)),
                                 longWait);
        // 100 % off by 0.5 mA: failed.
        m_bench.plc->setValue(addr("R100"), 31000);
        key(dialog, Qt::Key_V);
        QTRY_COMPARE_WITH_TIMEOUT(state(dialog, 0), resultText(CheckoutResult::Failed), longWait);
        // The transmitter adjusted, read again as left: passed, as found kept in the reading.
        m_bench.plc->setValue(addr("R100"), 32000);
        key(dialog, Qt::Key_V, Qt::ShiftModifier);
        QTRY_COMPARE_WITH_TIMEOUT(state(dialog, 0), resultText(CheckoutResult::Passed), longWait);
        QCOMPARE(pt.readings.back().asFound, std::optional<std::int64_t>(31000));
        QCOMPARE(pt.readings.back().asLeft, std::optional<std::int64_t>(32000));

        // A typed R200 has no scale: V and Space refused, the way out said.
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("stopButton")),
                          Qt::LeftButton);
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("newButton")),
                          Qt::LeftButton);
        QVERIFY(m_bench.startPlan(dialog, QStringLiteral("X0, R200"),
                                  QStringLiteral("noscale.checkout.json")));
        QVERIFY(watching(dialog));
        goTo(dialog, 1);
        QTRY_COMPARE_WITH_TIMEOUT(runner->currentPoint(), 1, longWait);
        QVERIFY(cell(dialog, 1, CheckoutTableModel::MeasuredColumn)
                    .startsWith(CheckoutTableModel::tr("no scale: import a plan CSV with it")));
        key(dialog, Qt::Key_V);
        QVERIFY2(dialog->messageText().startsWith(
                     translated(msg<MsgId::CheckoutAnalogNoScale>(std::string("R200")))),
                 qPrintable(dialog->messageText()));
        QVERIFY(dialog->messageText().contains(QLatin1String("Plan CSV")));
        key(dialog, Qt::Key_Space);
        QCOMPARE(dialog->messageText(),
                 translated(msg<MsgId::CheckoutMeasuredOnly>(std::string("R200"))));
        QCOMPARE(state(dialog, 1), resultText(CheckoutResult::Untested));
    }

    // A plan from the names imported in the main window, with a prefix (item 5); F2 on the Point
    // column edits the comment, and letters typed there are no test keys (item 6).
    void planFromNamesAndF2Anywhere()
    {
        IoCheckoutDialog *dialog = openTool();
        QVERIFY(dialog);
        const QString names = m_bench.files.filePath(QStringLiteral("names.csv"));
        QVERIFY(writeFile(names, "Address,Name,Comment\r\nX0,PB_Start,Start button\r\n"
                                 "X1,PB_Stop,Stop button\r\nY0,LAMP_Run,\r\nX5,LS_Door,\r\n"));
        QVERIFY(m_bench.window->importNames(names).ok());
        m_answers = {QStringLiteral("PB")};
        auto *import = dialog->findChild<QPushButton *>(QStringLiteral("importButton"));
        QVERIFY(pickFromMenu(import, "importNamesAction"));
        QCOMPARE(dialog->points()->rowCount(), 2);
        QCOMPARE(cell(dialog, 0, CheckoutTableModel::NameColumn), QStringLiteral("PB_Start"));
        QCOMPARE(cell(dialog, 1, CheckoutTableModel::NameColumn), QStringLiteral("PB_Stop"));

        QTableView *table = dialog->table();
        table->setFocus();
        table->setCurrentIndex(dialog->points()->index(0, CheckoutTableModel::PointColumn));
        key(dialog, Qt::Key_F2);
        QLineEdit *editor = nullptr;
        QTRY_VERIFY_WITH_TIMEOUT((editor = table->viewport()->findChild<QLineEdit *>())
                                     && editor->isVisible(),
                                 longWait);
        QTest::keyClicks(editor, QStringLiteral("FRAT wired"), {}, keyDelayMs);
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE_WITH_TIMEOUT(cell(dialog, 0, CheckoutTableModel::CommentColumn),
                                  QStringLiteral("FRAT wired"), longWait);
        QCOMPARE(state(dialog, 0), resultText(CheckoutResult::Untested));
        QVERIFY(m_asked.size() == 1); // only the prefix: no remark was asked

        // Typed ranges stay, and take the names too.
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("newButton")),
                          Qt::LeftButton);
        QVERIFY(
            m_bench.startPlan(dialog, QStringLiteral("X5"), QStringLiteral("x5.checkout.json")));
        QTRY_COMPARE_WITH_TIMEOUT(dialog->points()->rowCount(), 1, longWait);
        QCOMPARE(cell(dialog, 0, CheckoutTableModel::NameColumn), QStringLiteral("LS_Door"));
    }

    // A point the PLC refuses (X9999 on an FBs) is named at Start, and nothing runs.
    void refusedPointsNamed()
    {
        IoCheckoutDialog *dialog = openTool();
        QVERIFY(dialog);
        QVERIFY(m_bench.startPlan(dialog, QStringLiteral("X0, X9999"),
                                  QStringLiteral("refused.checkout.json")));
        QTRY_VERIFY_WITH_TIMEOUT(dialog->messageText().contains(QLatin1String("X9999")), longWait);
        QVERIFY(!dialog->runner()->isRunning());
        QVERIFY(dialog->findChild<QPushButton *>(QStringLiteral("startButton"))->isEnabled());
    }

    // Closing the dialog with Y3 forced: released in the PLC, the file lists nothing forced, the
    // next Open asks nothing (item 7).
    void closeReleasesAndClearsTheFile()
    {
        IoCheckoutDialog *dialog = openTool();
        QVERIFY(dialog);
        const QString file = forceY3(dialog, QStringLiteral("y3.checkout.json"));
        QVERIFY(!file.isEmpty());
        QCOMPARE(CheckoutFile::loadFromFile(file)->forced, std::vector<Address>{addr("Y3")});
        auto *box = dialog->findChild<QDialogButtonBox *>();
        QVERIFY(box && box->button(QDialogButtonBox::Close));
        QPointer<IoCheckoutDialog> open(dialog);
        QTest::mouseClick(box->button(QDialogButtonBox::Close), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!open || !open->isVisible(), longWait);
        QCOMPARE(m_bench.plc->isDisabled(addr("Y3")), std::optional<bool>(false));
        QCOMPARE(m_bench.plc->value(addr("Y3")), std::optional<std::uint32_t>(0));
        QVERIFY(CheckoutFile::loadFromFile(file)->forced.empty());
        QTRY_VERIFY_WITH_TIMEOUT(!open, longWait);

        IoCheckoutDialog *again = m_bench.openFromToolsMenu();
        QVERIFY(again);
        QStringList questions;
        answerYes(again, questions);
        QVERIFY(again->openCheckout(file));
        QVERIFY2(questions.isEmpty(), qPrintable(questions.join(QLatin1Char('\n'))));
    }

    // Closing while the PLC's answers are lost: the release cannot be confirmed; closing again
    // asks, and the file keeps Y3 listed for the next Open (item 7).
    void closeUnconfirmedAsksAndKeepsTheFile()
    {
        IoCheckoutDialog *dialog = openTool();
        QVERIFY(dialog);
        QStringList questions;
        answerYes(dialog, questions);
        const QString file = forceY3(dialog, QStringLiteral("lost.checkout.json"));
        QVERIFY(!file.isEmpty());
        FaultConfig lost;
        lost.dropRate = 1.0;
        m_bench.server->setFaults(lost);
        auto *box = dialog->findChild<QDialogButtonBox *>();
        QTest::mouseClick(box->button(QDialogButtonBox::Close), Qt::LeftButton);
        QVERIFY(dialog->isVisible());
        QVERIFY2(dialog->messageText().startsWith(QLatin1String("Releasing Y3")),
                 qPrintable(dialog->messageText()));
        QTRY_VERIFY_WITH_TIMEOUT(dialog->runner()->isRetryingRelease(), longWait);
        questions.clear();
        QPointer<IoCheckoutDialog> open(dialog);
        QTest::mouseClick(box->button(QDialogButtonBox::Close), Qt::LeftButton);
        QCOMPARE(questions.size(), 1);
        QVERIFY2(questions.front().contains(QLatin1String("Y3")), qPrintable(questions.front()));
        QTRY_VERIFY_WITH_TIMEOUT(!open || !open->isVisible(), longWait);
        QCOMPARE(CheckoutFile::loadFromFile(file)->forced, std::vector<Address>{addr("Y3")});
        m_bench.server->setFaults({});
    }

    // Closing the main window with Y3 forced: the checkout releases it first, the window closes
    // once the PLC confirmed it, and the file lists nothing forced (item 7).
    void quitReleasesAndClearsTheFile()
    {
        IoCheckoutDialog *dialog = openTool();
        QVERIFY(dialog);
        const QString file = forceY3(dialog, QStringLiteral("quit.checkout.json"));
        QVERIFY(!file.isEmpty());
        QPointer<IoCheckoutDialog> open(dialog);
        m_bench.window->close();
        QTRY_VERIFY2_WITH_TIMEOUT(!m_bench.window->isVisible(),
                                  qPrintable(open ? open->messageText() : QStringLiteral("gone")),
                                  longWait);
        QCOMPARE(m_bench.plc->isDisabled(addr("Y3")), std::optional<bool>(false));
        QVERIFY(CheckoutFile::loadFromFile(file)->forced.empty());
    }

    // Details… sets what the report prints (saved in the file); the punch list sets an owner,
    // refuses to close out what still fails, closes a deferral and exports its CSV; the report
    // as CSV with Windows line ends (items 8, 9).
    void detailsPunchListAndReports()
    {
        IoCheckoutDialog *dialog = openTool();
        QVERIFY(dialog);
        QVERIFY(m_bench.startPlan(dialog, QStringLiteral("X0..X1"),
                                  QStringLiteral("punch.checkout.json")));
        CheckoutRunner *runner = dialog->runner();
        QVERIFY(watching(dialog));
        QTRY_VERIFY_WITH_TIMEOUT(runner->isStarted() && runner->currentPoint() == 0, longWait);
        key(dialog, Qt::Key_F);
        goTo(dialog, 1);
        m_answers = {QStringLiteral("panel not powered")};
        key(dialog, Qt::Key_D);
        QCOMPARE(state(dialog, 1), resultText(CheckoutResult::Deferred));
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("stopButton")),
                          Qt::LeftButton);

        // Details, typed into their dialog.
        auto *details = dialog->findChild<QPushButton *>(QStringLiteral("detailsButton"));
        QVERIFY(details && details->isEnabled());
        UiTestUtil::answerModal([details] { QTest::mouseClick(details, Qt::LeftButton); },
                                [](QWidget *modal) {
                                    const auto type = [modal](const char *name, const char *text) {
                                        auto *edit = modal->findChild<QLineEdit *>(name);
                                        QVERIFY(edit);
                                        QTest::keyClicks(edit, QString::fromUtf8(text));
                                    };
                                    type("documentId", "SAT-0042");
                                    type("revision", "B");
                                    type("witness", "Chen");
                                    type("witnessCompany", "ACME Foods");
                                    type("customerSignatory", "Wang");
                                    auto *box = modal->findChild<QDialogButtonBox *>();
                                    QTest::mouseClick(box->button(QDialogButtonBox::Ok),
                                                      Qt::LeftButton);
                                });
        const auto saved = CheckoutFile::loadFromFile(runner->filePath());
        QVERIFY(saved.ok());
        QCOMPARE(saved->info.documentId, QStringLiteral("SAT-0042"));
        QCOMPARE(saved->info.revision, QStringLiteral("B"));
        QCOMPARE(saved->info.witness, QStringLiteral("Chen"));
        QCOMPARE(saved->info.witnessCompany, QStringLiteral("ACME Foods"));
        QCOMPARE(saved->info.customerSignatory, QStringLiteral("Wang"));

        // The punch list: both points, an owner typed, X0 cannot close while it fails.
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("punchButton")),
                          Qt::LeftButton);
        CheckoutPunchDialog *punch = dialog->punchDialog();
        QVERIFY(punch);
        QTRY_VERIFY_WITH_TIMEOUT(punch->isVisible(), longWait);
        QTableWidget *list = punch->table();
        QCOMPARE(list->rowCount(), 2);
        list->setFocus();
        list->setCurrentCell(0, CheckoutPunchDialog::OwnerColumn);
        QTest::keyClick(list, Qt::Key_F2);
        QLineEdit *editor = nullptr;
        QTRY_VERIFY_WITH_TIMEOUT(
            (editor = list->viewport()->findChild<QLineEdit *>()) && editor->isVisible(), longWait);
        QTest::keyClicks(editor, QStringLiteral("Electrician Lee"));
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE_WITH_TIMEOUT(runner->plan().points[0].punch.owner,
                                  QStringLiteral("Electrician Lee"), longWait);
        auto *closeOut = punch->findChild<QPushButton *>(QStringLiteral("closeOutButton"));
        list->setCurrentCell(0, 0);
        QTest::mouseClick(closeOut, Qt::LeftButton);
        QCOMPARE(punch->messageText(),
                 translated(msg<MsgId::CheckoutPunchStillFailing>(std::string("X0"))));
        list->setCurrentCell(1, 0);
        QTest::mouseClick(closeOut, Qt::LeftButton);
        QVERIFY(runner->plan().points[1].punch.closed.isValid());

        QString chosen = m_bench.files.filePath(QStringLiteral("punch.csv"));
        dialog->setFileChooser([&chosen](const ToolDialogFrame::FileQuestion &) { return chosen; });
        QTest::mouseClick(punch->findChild<QPushButton *>(QStringLiteral("exportPunchButton")),
                          Qt::LeftButton);
        const QByteArray punchCsv = readFile(chosen);
        QVERIFY2(punchCsv.startsWith("\xEF\xBB\xBF") && punchCsv.contains("Electrician Lee")
                     && punchCsv.contains("panel not powered") && !punchCsv.contains('\r'),
                 punchCsv.constData());
        // The second file type, "CSV, Windows line ends": the same list with CRLF.
        chosen = m_bench.files.filePath(QStringLiteral("punch-crlf.csv"));
        dialog->setFileChooser([&chosen](const ToolDialogFrame::FileQuestion &q) {
            if (q.selectedFilter
                && q.filter.split(QStringLiteral(";;")).contains(CsvFileFilter::windows()))
                *q.selectedFilter = CsvFileFilter::windows();
            return chosen;
        });
        QTest::mouseClick(punch->findChild<QPushButton *>(QStringLiteral("exportPunchButton")),
                          Qt::LeftButton);
        const QByteArray punchCrlf = readFile(chosen);
        QVERIFY2(punchCrlf.startsWith("\xEF\xBB\xBF") && punchCrlf.contains("Electrician Lee")
                     && punchCrlf.count('\n') == punchCrlf.count("\r\n")
                     && punchCrlf.contains("\r\n"),
                 punchCrlf.constData());
        punch->close();

        // The report as CSV with Windows line ends, and the details in it.
        chosen = m_bench.files.filePath(QStringLiteral("report-crlf.csv"));
        QVERIFY(pickFromMenu(dialog->findChild<QPushButton *>(QStringLiteral("reportButton")),
                             "reportCsvCrlfAction"));
        const QByteArray report = readFile(chosen);
        QVERIFY2(report.contains("SAT-0042\r\n") && !report.contains("\r\r")
                     && report.count('\n') == report.count("\r\n"),
                 report.constData());
    }
};

// A screen of a laptop's size: the offscreen platform reads it from a configuration file.
int main(int argc, char *argv[])
{
    const UiTestUtil::OffscreenScreen screen(laptop);
    if (!screen.isReady())
        return 1;
    QApplication app(argc, argv);
    TestUiCheckoutPlan test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_ui_checkoutplan.moc"
