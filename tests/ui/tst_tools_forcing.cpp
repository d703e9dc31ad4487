// ForcingPanel and its forced points view against the simulator running the demo ladder.
#include "tst_tools_fixture.h"
#include "ui/common/symbolnames.h"
#include "ui/tools/discretecontrolbatch.h"
#include "ui/tools/discretescan.h"
#include "ui/tools/discretetablemodel.h"
#include "ui/tools/forcedpointsview.h"
#include "ui/tools/forcingpanel.h"

#include <QItemSelectionModel>
#include <QListWidget>
#include <QPushButton>
#include <QTabBar>
#include <QTabWidget>
#include <QTableView>
#include <QTest>

using namespace Fatek;
using ToolsTest::addr;
using ToolsTest::Rig;

class TestToolsForcing : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void rangeParsing_data();
    void rangeParsing();
    void tableShowsStateAndForcing();
    void disableY0StopsTheLadder();
    void setResetMultiSelect();
    void declinedConfirmationSendsNothing();
    void refusedPointShownInWords();
    void scanCoversEveryPointOfThePlc();
    void noConnection();
    void operatorModeDisablesForcing();
    void namesNextToPoints();

private:
    void select(int first, int last);
    void waitForRead();

    Rig m_rig;
    std::unique_ptr<ForcingPanel> m_panel;
};

void TestToolsForcing::init()
{
    m_rig = Rig();
    QVERIFY(m_rig.start());
    m_panel = std::make_unique<ForcingPanel>();
    m_panel->setConfirmer(m_rig.confirmer());
    m_panel->setTarget(m_rig.target(1));
    m_panel->show();
}

void TestToolsForcing::cleanup()
{
    m_panel.reset();
    m_rig.link.reset();
    m_rig.server.reset();
    m_rig.plc.reset();
}

void TestToolsForcing::select(int first, int last)
{
    QTableView *view = m_panel->view();
    const QItemSelection selection(view->model()->index(first, 0),
                                   view->model()->index(last, DiscreteTableModel::ColumnCount - 1));
    view->selectionModel()->select(selection,
                                   QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
}

void TestToolsForcing::waitForRead()
{
    const int before = m_panel->readCount();
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->readCount() > before, 10000);
}

void TestToolsForcing::rangeParsing_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected"); // ranges joined by ";" or "error"
    QTest::newRow("one range") << "Y0-255"
                               << "Y0-255";
    QTest::newRow("dots, lower case") << "m100..199"
                                      << "M100-199";
    QTest::newRow("single point") << "X7"
                                  << "X7";
    QTest::newRow("repeated symbol") << "X16-X31"
                                     << "X16-31";
    QTest::newRow("list with spaces") << "X0-7, Y 0 - 15; S3"
                                      << "X0-7;Y0-15;S3";
    QTest::newRow("register type") << "R0-10"
                                   << "error";
    QTest::newRow("reversed") << "Y10-2"
                              << "error";
    QTest::newRow("mixed types") << "X0-Y5"
                                 << "error";
    QTest::newRow("beyond range") << "M9990-10010"
                                  << "error";
    QTest::newRow("garbage") << "hello"
                             << "error";
    QTest::newRow("empty") << "  "
                           << "error";
}

void TestToolsForcing::rangeParsing()
{
    QFETCH(QString, text);
    QFETCH(QString, expected);
    const Result<QList<AddressRange>> ranges = DiscreteScan::parse(text);
    if (expected == QLatin1String("error")) {
        QVERIFY(!ranges);
        QVERIFY(!ranges.error().text().empty());
        return;
    }
    QVERIFY2(ranges.ok(), ranges.ok() ? "" : ranges.error().text().c_str());
    QStringList got;
    for (const AddressRange &r : *ranges)
        got << QString::fromStdString(r.toString());
    QCOMPARE(got.join(QLatin1Char(';')), expected);
}

void TestToolsForcing::tableShowsStateAndForcing()
{
    m_rig.plc->setRunning(false); // no ladder: values stay as set
    m_rig.plc->setValue(addr("M3"), 1);
    m_rig.plc->setDisabled(addr("M5"), true);
    m_panel->showRange(ElementType::M, 0, 8);
    waitForRead();
    DiscreteTableModel *model = m_panel->model();
    QCOMPARE(model->rowCount(), 8);
    QCOMPARE(model->index(3, DiscreteTableModel::PointColumn).data().toString(),
             QStringLiteral("M3"));
    QCOMPARE(model->stateAt(3), std::optional<bool>(true));
    QCOMPARE(model->stateAt(4), std::optional<bool>(false));
    QCOMPARE(model->disabledAt(5), std::optional<bool>(true));
    QCOMPARE(model->disabledAt(3), std::optional<bool>(false));
    QCOMPARE(model->index(3, DiscreteTableModel::StateColumn).data().toString(),
             QStringLiteral("ON"));
    QVERIFY(model->index(5, DiscreteTableModel::ForcedColumn)
                .data()
                .toString()
                .contains(QStringLiteral("disabled")));
    QVERIFY(model->index(5, 0).data(Qt::BackgroundRole).isValid());
    QVERIFY(!model->index(4, 0).data(Qt::BackgroundRole).isValid());
}

void TestToolsForcing::disableY0StopsTheLadder()
{
    m_rig.server->setDemoLadder(true);
    // Y0 blinks at 1 Hz while nothing forces it.
    bool seen[2] = {false, false};
    QTRY_VERIFY_WITH_TIMEOUT(
        (seen[m_rig.plc->value(addr("Y0")).value_or(0) & 1] = true, seen[0] && seen[1]), 10000);

    m_panel->showRange(ElementType::Y, 0, 8);
    waitForRead();
    select(0, 0);
    m_panel->applyToSelection(DiscreteOp::Disable);
    QCOMPARE(m_rig.questions.size(), 1);
    QVERIFY2(m_rig.questions.last().contains(QStringLiteral("Disable Y0")),
             qPrintable(m_rig.questions.last()));
    QVERIFY(m_rig.questions.last().contains(QStringLiteral("station 1")));
    QVERIFY(m_rig.questions.last().contains(Rig::connectionName()));
    QTRY_COMPARE_WITH_TIMEOUT(m_rig.plc->isDisabled(addr("Y0")), std::optional<bool>(true), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->messageText().contains(QStringLiteral("Disabled 1 point")),
                             10000);
    QTRY_COMPARE_WITH_TIMEOUT(m_panel->model()->disabledAt(0), std::optional<bool>(true), 10000);

    // The ladder keeps running (R0 counts scans) but Y0 no longer changes: watch it for 2.5 blinks.
    const auto frozen = m_rig.plc->value(addr("Y0"));
    const auto scans = m_rig.plc->scanCount();
    for (int i = 0; i < 25; ++i) {
        QTest::qWait(100);
        QCOMPARE(m_rig.plc->value(addr("Y0")), frozen);
    }
    QVERIFY(m_rig.plc->scanCount() > scans);

    // The forced points view lists it.
    ForcedPointsView *forced = m_panel->forcedPointsView();
    forced->setRanges(QStringLiteral("X0-255, Y0-255, M0-1023"));
    forced->scan();
    QTRY_VERIFY_WITH_TIMEOUT(forced->scanCount() == 1, 10000);
    QCOMPARE(forced->forcedPoints(), QList<Address>{addr("Y0")});
    QVERIFY2(forced->messageText().contains(QStringLiteral("1 forced point")),
             qPrintable(forced->messageText()));

    // Enable all (confirmed) clears it, and the ladder drives Y0 again.
    forced->enableAll();
    QCOMPARE(m_rig.questions.size(), 2);
    QVERIFY2(m_rig.questions.last().contains(QStringLiteral("Enable Y0")),
             qPrintable(m_rig.questions.last()));
    QVERIFY(m_rig.questions.last().contains(Rig::connectionName()));
    QTRY_COMPARE_WITH_TIMEOUT(m_rig.plc->isDisabled(addr("Y0")), std::optional<bool>(false), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(forced->scanCount() == 2, 10000);
    QVERIFY(forced->forcedPoints().isEmpty());
    QVERIFY2(forced->messageText().contains(QStringLiteral("Enabled 1 point")),
             qPrintable(forced->messageText()));
    QTRY_COMPARE_WITH_TIMEOUT(m_rig.plc->value(addr("Y0")).value_or(0) != frozen.value_or(0), true,
                              10000);
    QTRY_COMPARE_WITH_TIMEOUT(m_panel->model()->disabledAt(0), std::optional<bool>(false), 10000);
}

void TestToolsForcing::setResetMultiSelect()
{
    m_rig.plc->setRunning(false);
    m_panel->showRange(ElementType::M, 10, 16);
    waitForRead();
    select(0, 2); // M10..M12
    m_panel->applyToSelection(DiscreteOp::Set);
    QVERIFY(m_rig.questions.last().contains(QStringLiteral("M10, M11, M12")));
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->messageText().contains(QStringLiteral("Set ON 3 points")),
                             10000);
    for (const char *a : {"M10", "M11", "M12"})
        QCOMPARE(m_rig.plc->value(addr(a)), std::optional<std::uint32_t>(1));
    QCOMPARE(m_rig.plc->value(addr("M13")), std::optional<std::uint32_t>(0));
    QTRY_COMPARE_WITH_TIMEOUT(m_panel->model()->stateAt(2), std::optional<bool>(true), 10000);

    select(1, 1);
    m_panel->applyToSelection(DiscreteOp::Reset);
    QTRY_COMPARE_WITH_TIMEOUT(m_rig.plc->value(addr("M11")), std::optional<std::uint32_t>(0),
                              10000);
    QCOMPARE(m_rig.plc->value(addr("M10")), std::optional<std::uint32_t>(1));
}

void TestToolsForcing::declinedConfirmationSendsNothing()
{
    m_rig.answer = false;
    m_panel->showRange(ElementType::Y, 0, 8);
    waitForRead();
    select(0, 3);
    m_panel->applyToSelection(DiscreteOp::Disable);
    QCOMPARE(m_rig.questions.size(), 1);
    QVERIFY(m_panel->messageText().contains(QStringLiteral("Cancelled")));
    waitForRead();
    for (const char *a : {"Y0", "Y1", "Y2", "Y3"})
        QCOMPARE(m_rig.plc->isDisabled(addr(a)), std::optional<bool>(false));

    ForcedPointsView *forced = m_panel->forcedPointsView();
    m_rig.plc->setDisabled(addr("Y2"), true);
    forced->setRanges(QStringLiteral("Y0-15"));
    forced->scan();
    QTRY_VERIFY_WITH_TIMEOUT(forced->scanCount() == 1, 10000);
    forced->enableAll();
    QCOMPARE(m_rig.questions.size(), 2);
    QTest::qWait(200);
    QCOMPARE(m_rig.plc->isDisabled(addr("Y2")), std::optional<bool>(true));
}

void TestToolsForcing::refusedPointShownInWords()
{
    // The FBs profile has fewer Y than the protocol allows: beyond it the PLC answers error A.
    const quint32 beyond = m_rig.plc->profile().size(ElementType::Y);
    m_panel->showRange(ElementType::Y, beyond - 2, 4);
    waitForRead();
    QVERIFY2(m_panel->messageText().contains(QStringLiteral("PLC error A")),
             qPrintable(m_panel->messageText()));
    ForcedPointsView *forced = m_panel->forcedPointsView();
    forced->setRanges(QStringLiteral("Y%1-%2").arg(beyond).arg(beyond + 3));
    forced->scan();
    QTRY_VERIFY_WITH_TIMEOUT(forced->scanCount() == 1, 10000);
    QVERIFY2(forced->messageText().contains(QStringLiteral("Scan incomplete")),
             qPrintable(forced->messageText()));
    // A mixed range is refused in AddressRange's words (watch lists say the same).
    forced->setRanges(QStringLiteral("Y0-R5"));
    forced->scan();
    QVERIFY2(forced->messageText().contains(QStringLiteral("same element type")),
             qPrintable(forced->messageText()));
}

// Issue 16.3: points beyond the old default ranges (M0-1023, S0-255) are found and enabled, with
// the mouse, and the view says what it scanned.
void TestToolsForcing::scanCoversEveryPointOfThePlc()
{
    for (const char *a : {"M1500", "M2001", "S900", "X3"})
        m_rig.plc->setDisabled(addr(a), true);
    auto *tabs = m_panel->findChild<QTabWidget *>();
    QVERIFY(tabs);
    ForcedPointsView *forced = m_panel->forcedPointsView();
    QTabBar *bar = tabs->tabBar();
    QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(tabs->indexOf(forced)).center(), 200);
    QTRY_VERIFY(forced->isVisible());
    auto *scan = forced->findChild<QPushButton *>(QStringLiteral("scanButton"));
    auto *enableAll = forced->findChild<QPushButton *>(QStringLiteral("enableAllButton"));
    QVERIFY(scan && enableAll);
    QTest::mouseClick(scan, Qt::LeftButton, {}, {}, 200);
    QTRY_COMPARE_WITH_TIMEOUT(forced->scanCount(), 1, 10000);
    const QList<Address> expected{addr("X3"), addr("M1500"), addr("M2001"), addr("S900")};
    QCOMPARE(forced->forcedPoints(), expected);
    QCOMPARE(forced->findChild<QListWidget *>()->count(), 4);
    // The sizes come from the PLC's 53 answer (FBs: M0-2001, S0-999).
    QCOMPARE(forced->scannedText(),
             QStringLiteral("X0-255, Y0-255, M0-2001, S0-999, T0-255, C0-255"));
    QVERIFY2(forced->messageText().contains(QStringLiteral("Scanned X0-255, Y0-255, M0-2001, "
                                                           "S0-999, T0-255, C0-255")),
             qPrintable(forced->messageText()));
    QVERIFY2(forced->messageText().contains(QStringLiteral("4 forced points")),
             qPrintable(forced->messageText()));

    QTRY_VERIFY(enableAll->isEnabled());
    QTest::mouseClick(enableAll, Qt::LeftButton, {}, {}, 200);
    QCOMPARE(m_rig.questions.size(), 1);
    QTRY_COMPARE_WITH_TIMEOUT(forced->scanCount(), 2, 10000);
    for (const char *a : {"M1500", "M2001", "S900", "X3"})
        QCOMPARE(m_rig.plc->isDisabled(addr(a)), std::optional<bool>(false));
    QVERIFY(forced->forcedPoints().isEmpty());
    QVERIFY2(forced->messageText().contains(QStringLiteral("no forced points")),
             qPrintable(forced->messageText()));
}

void TestToolsForcing::noConnection()
{
    m_panel->setTarget(PlcTarget());
    m_panel->applyToSelection(DiscreteOp::Disable);
    m_panel->forcedPointsView()->scan();
    m_panel->forcedPointsView()->enableAll();
    QVERIFY(m_rig.questions.isEmpty());
    QCOMPARE(m_panel->forcedPointsView()->scanCount(), 0);
}

void TestToolsForcing::operatorModeDisablesForcing()
{
    m_panel->showRange(ElementType::Y, 0, 8);
    waitForRead();
    select(0, 1);
    auto *disable = m_panel->findChild<QPushButton *>(QStringLiteral("disableButton"));
    QVERIFY(disable->isEnabled());
    m_rig.link->setReadOnly(true);
    QTRY_VERIFY_WITH_TIMEOUT(!disable->isEnabled(), 10000);
    m_panel->applyToSelection(
        DiscreteOp::Disable); // called anyway: refused by the session, in words
    QTRY_VERIFY_WITH_TIMEOUT(m_panel->messageText().contains(QStringLiteral("Read-only mode")),
                             10000);
    QCOMPARE(m_rig.plc->isDisabled(addr("Y0")), std::optional<bool>(false));
}

void TestToolsForcing::namesNextToPoints()
{
    // The window's names (File > Import Names and Comments…): beside each point of the table,
    // the comment in its tooltip, and with each forced point.
    SymbolNames names;
    SymbolTable table;
    table.insert(addr("Y0"), {QStringLiteral("Blink lamp"), QStringLiteral("panel, top left")});
    table.insert(addr("Y2"), {QStringLiteral("Pump"), {}});
    names.setTable(table);
    m_panel->setSymbols(&names);
    m_panel->showRange(ElementType::Y, 0, 4);
    waitForRead();
    DiscreteTableModel *model = m_panel->model();
    QCOMPARE(model->headerData(DiscreteTableModel::NameColumn, Qt::Horizontal).toString(),
             QStringLiteral("Name"));
    QCOMPARE(model->index(0, DiscreteTableModel::NameColumn).data().toString(),
             QStringLiteral("Blink lamp"));
    QCOMPARE(model->index(0, DiscreteTableModel::PointColumn).data(Qt::ToolTipRole).toString(),
             QStringLiteral("panel, top left"));
    QCOMPARE(model->index(1, DiscreteTableModel::NameColumn).data().toString(), QString());

    // Names imported later show at once.
    SymbolTable more;
    more.insert(addr("Y1"), {QStringLiteral("Horn"), {}});
    names.merge(more);
    QCOMPARE(model->index(1, DiscreteTableModel::NameColumn).data().toString(),
             QStringLiteral("Horn"));

    QVERIFY(m_rig.plc->setDisabled(addr("Y2"), true));
    ForcedPointsView *forced = m_panel->forcedPointsView();
    forced->setRanges(QStringLiteral("Y0-15"));
    forced->scan();
    QTRY_VERIFY_WITH_TIMEOUT(forced->scanCount() == 1, 10000);
    QCOMPARE(forced->listedTexts(), QStringList{QStringLiteral("Y2 Pump")});
    QVERIFY(m_rig.plc->setDisabled(addr("Y2"), false));
}

QTEST_MAIN(TestToolsForcing)
#include "tst_tools_forcing.moc"
