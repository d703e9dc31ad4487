// Issue 54, item 7: displays that misled now show the truth, in the main window at 1366x768
// against the demo PLC (real, over loopback TCP) and an M-series simulator: the Tools menu ticks
// only the docks that are open; a row moved to another station waits for that station instead of
// showing the old one's value as good; a refused element keeps its reason while nothing is read;
// the table's Pause button says Resume when paused; a new row is scrolled into view; Ctrl+Up
// under a filter says why it does nothing; a "Read-only mode" failure goes with operator mode;
// an M-series PLC is named by its family in the connections list.
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "demowindow.h"
#include "testutil.h"
#include "ui/common/messageline.h"
#include "ui/connection/connection.h"
#include "ui/connection/connectionlistmodel.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/mainwindow/operatormode.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtablewidget.h"
#include "uitestutil.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

using namespace Fatek;

namespace {

constexpr int longWait = 20000;

int rowOf(const QAbstractItemModel *model, const QString &address)
{
    for (int r = 0; r < model->rowCount(); ++r) {
        if (model->index(r, WatchTableModel::AddressColumn).data().toString() == address)
            return r;
    }
    return -1;
}

QString cell(const WatchTableModel *model, int row, int column, int role = Qt::DisplayRole)
{
    return model->index(row, column).data(role).toString();
}

} // namespace

class TestUiTruth : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;
    std::unique_ptr<MainWindow> m_window;

    bool openDemo() { return UiTestUtil::openDemoWindow(m_window, false, longWait); }

    WatchTableWidget *table() const { return m_window->currentWatchTable(); }
    WatchTableModel *model() const { return table()->model(); }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_truth"));
        registerSessionMetaTypes();
    }

    void cleanup()
    {
        m_window.reset();
        QSettings().clear();
    }

    // First start: the Tools menu ticks what is on screen, nothing else.
    void toolsMenuTicksOpenDocks()
    {
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        // The Tools menu: the first of the menu bar's menus with the PLC Control entry.
        QAction *control = m_window->findChild<QAction *>(QStringLiteral("plcControlDockAction"));
        QVERIFY(control);
        QMenu *tools = nullptr;
        for (QAction *a : m_window->menuBar()->actions()) {
            if (!tools && a->menu() && a->menu()->actions().contains(control))
                tools = a->menu();
        }
        QVERIFY(tools);
        tools->popup(m_window->mapToGlobal(QPoint(10, 10)));
        QVERIFY(QTest::qWaitForWindowExposed(tools));
        for (const char *name : {"plcControlDock", "forcingDock", "rawConsoleDock", "trendDock"}) {
            auto *dock = m_window->findChild<QDockWidget *>(QLatin1String(name));
            QAction *action = m_window->findChild<QAction *>(QLatin1String(name) + "Action");
            if (!action && dock)
                action = dock->toggleViewAction(); // the trend's own entry
            QVERIFY2(dock && action, name);
            QVERIFY2(action->isChecked() == !dock->isHidden(),
                     qPrintable(QStringLiteral("%1 ticked %2, open %3")
                                    .arg(QLatin1String(name))
                                    .arg(action->isChecked())
                                    .arg(!dock->isHidden())));
        }
        QVERIFY(
            !m_window->findChild<QAction *>(QStringLiteral("plcControlDockAction"))->isChecked());
        tools->close();
        // Opened: ticked.
        QVERIFY(m_window->openTool(QStringLiteral("forcing")));
        QTRY_VERIFY(
            m_window->findChild<QAction *>(QStringLiteral("forcingDockAction"))->isChecked());
    }

    // R0 moved from station 1 to station 7 (no such PLC): its old value is not station 7's.
    void stationChangeDropsTheOldValue()
    {
        QVERIFY(openDemo());
        const int row = rowOf(model(), QStringLiteral("R0"));
        QVERIFY(row >= 0);
        QTRY_VERIFY_WITH_TIMEOUT(
            cell(model(), row, WatchTableModel::QualityColumn).startsWith(QStringLiteral("good")),
            longWait);
        QVERIFY(model()->setData(model()->index(row, WatchTableModel::StationColumn), 7));
        // At once and from then on: no value, and never "good".
        for (int i = 0; i < 20; ++i) {
            const QString quality = cell(model(), row, WatchTableModel::QualityColumn);
            QVERIFY2(!quality.startsWith(QStringLiteral("good")), qPrintable(quality));
            QCOMPARE(cell(model(), row, WatchTableModel::ValueColumn), QStringLiteral("…"));
            QTest::qWait(100);
        }
        // Back on station 1: its values again.
        QVERIFY(model()->setData(model()->index(row, WatchTableModel::StationColumn), 1));
        QTRY_VERIFY_WITH_TIMEOUT(
            cell(model(), row, WatchTableModel::QualityColumn).startsWith(QStringLiteral("good")),
            longWait);
    }

    // An element the PLC refuses keeps its error and reason while the table is paused (or the
    // link down): it never turns "waiting".
    void refusedElementKeepsItsReason()
    {
        WatchTableModel m;
        WatchItemSpec spec;
        spec.address = *Address::parse("R5000");
        spec.station = 1;
        m.addItems({spec});
        WatchItemValue value;
        value.key = m.watchItems(500).constFirst().key;
        value.quality = ValueQuality::Error;
        value.error = Message::text("PLC error 2: the element does not exist");
        m.applyValues({value});
        QCOMPARE(cell(&m, 0, WatchTableModel::QualityColumn), QStringLiteral("error"));
        m.markAllStale(QStringLiteral("link lost"));
        QCOMPARE(cell(&m, 0, WatchTableModel::QualityColumn), QStringLiteral("error"));
        QVERIFY2(cell(&m, 0, WatchTableModel::QualityColumn, Qt::ToolTipRole)
                     .contains(QStringLiteral("does not exist")),
                 qPrintable(cell(&m, 0, WatchTableModel::QualityColumn, Qt::ToolTipRole)));
    }

    // Pause says Resume once paused; a row added at the end comes into view; Ctrl+Up under a
    // filter says why nothing moved.
    void tableSaysWhatItDoes()
    {
        QVERIFY(openDemo());
        auto *pause = table()->findChild<QToolButton *>(QStringLiteral("pauseButton"));
        QVERIFY(pause);
        QCOMPARE(pause->text(), QStringLiteral("Pause"));
        QTest::mouseClick(pause, Qt::LeftButton);
        QVERIFY(table()->isPaused());
        QCOMPARE(pause->text(), QStringLiteral("Resume"));
        QTest::mouseClick(pause, Qt::LeftButton);
        QCOMPARE(pause->text(), QStringLiteral("Pause"));

        const int rowsBefore = model()->rowCount();
        QLineEdit *add = table()->addressEdit();
        QTest::mouseClick(add, Qt::LeftButton);
        QTest::keyClicks(add, QStringLiteral("R100..R139"));
        QTest::keyClick(add, Qt::Key_Return);
        QTableView *view = table()->view();
        QCOMPARE(model()->rowCount(), rowsBefore + 40);
        const QModelIndex last = view->model()->index(view->model()->rowCount() - 1, 0);
        QTest::qWait(50);
        QVERIFY2(view->viewport()->rect().contains(view->visualRect(last)),
                 qPrintable(QStringLiteral("the new last row at y %1, the table shows 0..%2")
                                .arg(view->visualRect(last).y())
                                .arg(view->viewport()->height())));

        QLineEdit *filter = table()->filterEdit();
        QTest::mouseClick(filter, Qt::LeftButton);
        QTest::keyClicks(filter, QStringLiteral("R1"));
        QTRY_VERIFY(view->model()->rowCount() < model()->rowCount());
        view->setFocus();
        view->setCurrentIndex(view->model()->index(1, 0));
        auto *message = table()->findChild<MessageLine *>(QStringLiteral("messageLabel"));
        QVERIFY(message);
        const QString before = message->text();
        QTest::keyClick(view, Qt::Key_Up, Qt::ControlModifier);
        QTRY_VERIFY(message->text() != before);
        QVERIFY2(message->text().contains(QStringLiteral("filter")), qPrintable(message->text()));
    }

    // A write refused in operator mode says "Read-only mode"; once operator mode is off the
    // table no longer says so.
    void readOnlyFailureGoesWithOperatorMode()
    {
        QVERIFY(openDemo());
        auto *mode = m_window->findChild<OperatorMode *>();
        QVERIFY(mode);
        mode->setAsker([](const QString &, bool, QString *) { return true; });
        mode->toggleAction()->trigger();
        QVERIFY(mode->isActive());
        const int row = rowOf(model(), QStringLiteral("R0"));
        QVERIFY(row >= 0);
        model()->setData(model()->index(row, WatchTableModel::ValueColumn), QStringLiteral("5"));
        auto *message = table()->findChild<MessageLine *>(QStringLiteral("messageLabel"));
        QVERIFY(message);
        QTRY_VERIFY_WITH_TIMEOUT(message->text().contains(QStringLiteral("failed")), longWait);
        mode->toggleAction()->trigger();
        QVERIFY(!mode->isActive());
        QVERIFY2(!message->text().contains(QStringLiteral("failed"))
                     && !message->text().contains(QStringLiteral("Read-only")),
                 qPrintable(message->text()));
        QVERIFY2(message->text().contains(QStringLiteral("not written")),
                 qPrintable(message->text()));
    }

    // An M-series PLC has no documented model name: the connections list names its family
    // beside RUN/STOP.
    void mSeriesNamedByItsFamily()
    {
        SimulatedPlc plc(ModelProfile::mSeries());
        plc.setRunning(true);
        SimServer server(&plc);
        QVERIFY(server.listenTcp(0));
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        SavedConnection saved;
        saved.name = QStringLiteral("M PLC");
        saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.tcpPort());
        Connection *c = m_window->openConnection(saved, false);
        QVERIFY(c);
        QTRY_VERIFY_WITH_TIMEOUT(c->plcText().contains(QStringLiteral("RUN")), longWait);
        QVERIFY2(c->plcText().contains(QStringLiteral("M series")), qPrintable(c->plcText()));
        m_window.reset();
    }
};

int main(int argc, char *argv[])
{
    const UiTestUtil::OffscreenScreen screen(QSize(1366, 768));
    if (!screen.isReady())
        return 1;
    QApplication app(argc, argv);
    TestUiTruth test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_ui_truth.moc"
