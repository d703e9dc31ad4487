// The real main window against an in-process simulator: connect, add items by address and by
// range, watch values arrive and change, write a register and a discrete, see stale marks when the
// simulator stops, save and reload a watch list, reject bad input, operator mode, the demo.
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"
#include "ui/connection/connectiondialog.h"
#include "ui/connection/connectionmanager.h"
#include "ui/mainwindow/demosimulator.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/tools/rawconsole.h"
#include "ui/tools/trafficlogmodel.h"
#include "ui/watch/watchtablemodel.h"

#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStyle>
#include <QStyleOptionViewItem>
#include <QTabBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <memory>

using namespace Fatek;

namespace {

constexpr int longWait = 20000;

Address addr(const char *text)
{
    return *Address::parse(text);
}

// A simulated FBs PLC on a free TCP port of this process.
struct Plc
{
    SimulatedPlc plc;
    SimServer server{&plc};
    quint16 port = 0;

    Plc()
    {
        QString error;
        if (server.listenTcp(0, &error))
            port = server.tcpPort();
        else
            qWarning("cannot listen: %s", qPrintable(error));
    }
};

SavedConnection savedFor(quint16 port)
{
    SavedConnection saved;
    saved.name = QStringLiteral("Test PLC");
    saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), port);
    saved.settings.timeoutMs = 300;
    saved.settings.retries = 0;
    saved.station = 1;
    return saved;
}

void typeInto(QLineEdit *edit, const QString &text)
{
    edit->setFocus();
    edit->clear();
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
}

int rowOf(const WatchTableModel *model, const char *address)
{
    for (int r = 0; r < model->rowCount(); ++r) {
        if (model->item(r).address == addr(address))
            return r;
    }
    return -1;
}

} // namespace

class TestUiMainWindow : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;

    // A window connected to `plc`, with its first table bound to the connection.
    static Connection *connect(MainWindow &window, Plc &plc)
    {
        Connection *c = window.openConnection(savedFor(plc.port));
        return c;
    }

private Q_SLOTS:
    void initTestCase()
    {
        // Keep the developer's own settings out of the tests.
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_mainwindow"));
    }

    void connectAddAndWatchValuesChange()
    {
        Plc plc;
        QVERIFY(plc.port != 0);
        plc.plc.setValue(addr("R100"), 1234);
        plc.plc.setValue(addr("X2"), 1);
        MainWindow window;
        window.show();
        Connection *c = connect(window, plc);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        WatchTableWidget *table = window.currentWatchTable();
        QVERIFY(table);
        QCOMPARE(table->connection(), c);

        typeInto(table->addressEdit(), QStringLiteral("R100"));
        typeInto(table->addressEdit(), QStringLiteral("X0..X7"));
        WatchTableModel *model = table->model();
        QCOMPARE(model->rowCount(), 9);
        QVERIFY(table->addressEdit()->text().isEmpty());

        const int r100 = rowOf(model, "R100");
        const int x2 = rowOf(model, "X2");
        const int x3 = rowOf(model, "X3");
        QTRY_COMPARE_WITH_TIMEOUT(model->valueText(r100), QStringLiteral("1234"), longWait);
        QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(x3), longWait);
        QCOMPARE(model->index(x2, WatchTableModel::ValueColumn).data(Qt::CheckStateRole).toInt(),
                 int(Qt::Checked));
        QCOMPARE(model->index(x3, WatchTableModel::ValueColumn).data(Qt::CheckStateRole).toInt(),
                 int(Qt::Unchecked));
        QCOMPARE(model->quality(r100), ValueQuality::Good);

        // The PLC changes: the table follows.
        plc.plc.setValue(addr("R100"), static_cast<std::uint32_t>(-5 & 0xFFFF));
        QTRY_COMPARE_WITH_TIMEOUT(model->valueText(r100), QStringLiteral("-5"), longWait);
        QVERIFY(!model->index(r100, WatchTableModel::UpdatedColumn).data().toString().isEmpty());
        // The status bar and the connections panel show the link.
        auto *linkStatus = window.findChild<QLabel *>(QStringLiteral("linkStatus"));
        QVERIFY(linkStatus);
        QTRY_VERIFY_WITH_TIMEOUT(linkStatus->text().contains(QStringLiteral("connected")),
                                 longWait);
        QTRY_VERIFY_WITH_TIMEOUT(c->statistics().total.requests > 0, longWait);
    }

    // The raw console behind the Connections tab reads nothing: the link keeps its short log and
    // the console's table stays empty. A click on its tab shows it: the frames come, and the log
    // keeps its full length from then on.
    void consoleReadsTheLogOnlyWhenItsTabIsChosen()
    {
        Plc plc;
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        Connection *c = connect(window, plc);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        typeInto(window.currentWatchTable()->addressEdit(), QStringLiteral("R0..R9"));
        auto *console = window.findChild<RawConsole *>();
        QVERIFY(console);
        TrafficLog *log = c->session()->trafficLog();
        QTRY_VERIFY_WITH_TIMEOUT(log->lastSequence() > 20, longWait);
        QCOMPARE(console->model()->rowCount(), 0);
        QCOMPARE(log->capacity(), TrafficLog::idleCapacity);

        QTabBar *tabs = nullptr;
        int consoleTab = -1;
        // The dock's tab names the PLC too ("Raw Console — Test PLC, station 1").
        const QString title
            = window.findChild<QDockWidget *>(QStringLiteral("rawConsoleDock"))->windowTitle();
        QVERIFY2(title.startsWith(QLatin1String("Raw Console")), qPrintable(title));
        for (QTabBar *bar : window.findChildren<QTabBar *>()) {
            for (int i = 0; i < bar->count(); ++i) {
                if (bar->isVisible() && bar->tabText(i) == title) {
                    tabs = bar;
                    consoleTab = i;
                }
            }
        }
        QVERIFY(tabs);
        QTest::mouseClick(tabs, Qt::LeftButton, {}, tabs->tabRect(consoleTab).center(), 300);
        QTRY_VERIFY(console->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(console->model()->rowCount() > 0, longWait);
        QCOMPARE(log->capacity(), TrafficLog::fullCapacity);
    }

    void editRegisterAndToggleDiscrete()
    {
        Plc plc;
        MainWindow window;
        int confirmations = 0;
        window.setConfirmHandler([&](QWidget *, const QString &question) {
            ++confirmations;
            return !question.contains(QStringLiteral("R101")); // R101: the user says no
        });
        window.show();
        Connection *c = connect(window, plc);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        WatchTableWidget *table = window.currentWatchTable();
        typeInto(table->addressEdit(), QStringLiteral("R100 R101 Y0"));
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(0) && model->hasValue(1) && model->hasValue(2),
                                 longWait);

        // Edit in place: the view's editor, as a technician types it.
        QTableView *view = table->view();
        const QModelIndex value = table->viewIndex(model->index(0, WatchTableModel::ValueColumn));
        view->setCurrentIndex(value);
        view->edit(value);
        auto *editor = view->viewport()->findChild<QLineEdit *>();
        QVERIFY(editor);
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("0x2A"));
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE_WITH_TIMEOUT(plc.plc.value(addr("R100")).value_or(0), 42u, longWait);
        QCOMPARE(confirmations, 1);
        QTRY_VERIFY_WITH_TIMEOUT(table->message().startsWith(QStringLiteral("Wrote R100")),
                                 longWait);
        QTRY_COMPARE_WITH_TIMEOUT(model->valueText(0), QStringLiteral("42"), longWait);
        // The traffic log records the write.
        bool logged = false;
        for (const TrafficEntry &e : c->session()->trafficLog()->entries())
            logged = logged || englishText(e.summary).contains(QStringLiteral("write"));
        QVERIFY(logged);

        // Refused confirmation: nothing is written.
        model->setData(model->index(1, WatchTableModel::ValueColumn), QStringLiteral("9"));
        QTRY_COMPARE_WITH_TIMEOUT(confirmations, 2, longWait);
        QVERIFY(table->message().contains(QStringLiteral("cancelled")));

        // A discrete toggles with a click on its box.
        const QModelIndex y0 = model->index(2, WatchTableModel::ValueColumn);
        QCOMPARE(y0.data(Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
        QStyleOptionViewItem option;
        option.initFrom(view->viewport());
        option.rect = view->visualRect(table->viewIndex(y0));
        option.features
            = QStyleOptionViewItem::HasCheckIndicator | QStyleOptionViewItem::HasDisplay;
        option.text = y0.data().toString();
        const QRect box
            = view->style()->subElementRect(QStyle::SE_ItemViewItemCheckIndicator, &option, view);
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, box.center());
        QTRY_COMPARE_WITH_TIMEOUT(plc.plc.value(addr("Y0")).value_or(0), 1u, longWait);
        QTRY_COMPARE_WITH_TIMEOUT(y0.data(Qt::CheckStateRole).toInt(), int(Qt::Checked), longWait);
        QCOMPARE(confirmations, 3);

        // Without confirmation, no question is asked.
        table->setConfirmWrites(false);
        model->setData(model->index(1, WatchTableModel::ValueColumn), QStringLiteral("-2"));
        QTRY_COMPARE_WITH_TIMEOUT(plc.plc.value(addr("R101")).value_or(0), 0xFFFEu, longWait);
        QCOMPARE(confirmations, 3);
    }

    void twoTablesShareOneConnectionAndPause()
    {
        Plc plc;
        plc.plc.setValue(addr("R100"), 10);
        plc.plc.setValue(addr("R200"), 20);
        MainWindow window;
        window.show();
        Connection *c = connect(window, plc);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        WatchTableWidget *first = window.currentWatchTable();
        typeInto(first->addressEdit(), QStringLiteral("R100"));
        WatchTableWidget *second = window.addWatchTable(QStringLiteral("Second"));
        QCOMPARE(second->connection(), c);
        second->setIntervalMs(100);
        // Pasted rows keep their names.
        QVERIFY(second->addFromPaste(QStringLiteral("R200\tTank level\nR201\tPump speed\n")));
        QCOMPARE(second->model()->rowCount(), 2);
        QCOMPARE(second->model()->item(0).name, QStringLiteral("Tank level"));
        QTRY_COMPARE_WITH_TIMEOUT(first->model()->valueText(0), QStringLiteral("10"), longWait);
        QTRY_COMPARE_WITH_TIMEOUT(second->model()->valueText(0), QStringLiteral("20"), longWait);

        // Pausing one table leaves the other polling.
        first->setPaused(true);
        QCOMPARE(first->model()->quality(0), ValueQuality::Stale);
        QCOMPARE(first->model()->qualityReason(0), QStringLiteral("polling paused"));
        plc.plc.setValue(addr("R100"), 11);
        plc.plc.setValue(addr("R200"), 21);
        QTRY_COMPARE_WITH_TIMEOUT(second->model()->valueText(0), QStringLiteral("21"), longWait);
        QCOMPARE(first->model()->valueText(0), QStringLiteral("10"));
        first->setPaused(false);
        QTRY_COMPARE_WITH_TIMEOUT(first->model()->valueText(0), QStringLiteral("11"), longWait);
        QCOMPARE(first->model()->quality(0), ValueQuality::Good);
    }

    void refusedElementIsMarkedWithReason()
    {
        Plc plc;
        plc.plc.setValue(addr("R100"), 3);
        MainWindow window;
        window.show();
        Connection *c = connect(window, plc);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        WatchTableWidget *table = window.currentWatchTable();
        // R3900 exists on larger models but not on this FBs: the PLC answers error A.
        typeInto(table->addressEdit(), QStringLiteral("R100 R3900"));
        WatchTableModel *model = table->model();
        QTRY_COMPARE_WITH_TIMEOUT(model->quality(1), ValueQuality::Error, longWait);
        QTRY_COMPARE_WITH_TIMEOUT(model->valueText(0), QStringLiteral("3"), longWait);
        QCOMPARE(model->quality(0), ValueQuality::Good);
        const QModelIndex quality = model->index(1, WatchTableModel::QualityColumn);
        QCOMPARE(quality.data().toString(), QStringLiteral("error"));
        QVERIFY2(quality.data(Qt::ToolTipRole).toString().contains(QStringLiteral("R3900")),
                 qPrintable(quality.data(Qt::ToolTipRole).toString()));
        QVERIFY(!model->hasValue(1));
    }

    void badValueAndBadAddressAreRejected()
    {
        MainWindow window;
        window.show();
        WatchTableWidget *table = window.currentWatchTable();
        typeInto(table->addressEdit(), QStringLiteral("R100 R99999"));
        QCOMPARE(table->model()->rowCount(), 0);
        QVERIFY2(table->message().contains(QStringLiteral("\"R99999\"")),
                 qPrintable(table->message()));
        // The text stays for correction.
        QCOMPARE(table->addressEdit()->text(), QStringLiteral("R100 R99999"));
        typeInto(table->addressEdit(), QStringLiteral("R10..R5"));
        QCOMPARE(table->model()->rowCount(), 0);
        QVERIFY(!table->message().isEmpty());
    }

    void staleAfterSimulatorStops()
    {
        auto plc = std::make_unique<Plc>();
        plc->plc.setValue(addr("R5"), 77);
        MainWindow window;
        window.show();
        Connection *c = connect(window, *plc);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        WatchTableWidget *table = window.currentWatchTable();
        typeInto(table->addressEdit(), QStringLiteral("R5"));
        WatchTableModel *model = table->model();
        QTRY_COMPARE_WITH_TIMEOUT(model->valueText(0), QStringLiteral("77"), longWait);
        plc.reset();
        QTRY_COMPARE_WITH_TIMEOUT(model->quality(0), ValueQuality::Stale, longWait);
        // The last value stays, marked, with the reason in the tooltip.
        QCOMPARE(model->valueText(0), QStringLiteral("77"));
        const QModelIndex quality = model->index(0, WatchTableModel::QualityColumn);
        // The quality, then the value's age ("stale, 0.1 s").
        QCOMPARE(quality.data().toString().section(QStringLiteral(", "), 0, 0),
                 QStringLiteral("stale"));
        QVERIFY(quality.data(Qt::ToolTipRole).toString().startsWith(QStringLiteral("stale: ")));
        QVERIFY(!model->qualityReason(0).isEmpty());
    }

    void saveAndReloadWatchList()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("list.json"));
        QList<WatchItemSpec> saved;
        {
            MainWindow window;
            WatchTableWidget *table = window.currentWatchTable();
            typeInto(table->addressEdit(), QStringLiteral("R100 DR10 X0..X1"));
            WatchTableModel *model = table->model();
            QVERIFY(model->setData(model->index(0, WatchTableModel::NameColumn),
                                   QStringLiteral("Tank level")));
            QVERIFY(model->setData(model->index(0, WatchTableModel::FormatColumn),
                                   QStringLiteral("float")));
            QVERIFY(model->setFormat(0, DisplayFormat::Float32, true).ok());
            table->setIntervalMs(250);
            table->setConfirmWrites(false);
            WatchTableWidget *second = window.addWatchTable(QStringLiteral("Second"));
            typeInto(second->addressEdit(), QStringLiteral("M7"));
            saved = model->items();
            const Status s = window.saveWatchList(path);
            QVERIFY2(s.ok(), s.ok() ? "" : s.error().text().c_str());
        }
        MainWindow window;
        const Status s = window.loadWatchList(path);
        QVERIFY2(s.ok(), s.ok() ? "" : s.error().text().c_str());
        QCOMPARE(window.watchTables().size(), 2);
        WatchTableWidget *table = window.watchTables().at(0);
        QCOMPARE(table->model()->items(), saved);
        QCOMPARE(table->model()->item(0).name, QStringLiteral("Tank level"));
        QCOMPARE(table->model()->item(0).format, DisplayFormat::Float32);
        QVERIFY(table->model()->item(0).swapWords);
        QCOMPARE(table->intervalMs(), 250);
        QVERIFY(!table->confirmWrites());
        QCOMPARE(window.watchTables().at(1)->name(), QStringLiteral("Second"));
        {
            // The next start reopens the list used last.
            MainWindow next;
            QCOMPARE(next.watchTables().size(), 1);
            QVERIFY(next.restoreLastWatchList());
            QCOMPARE(next.watchTables().size(), 2);
            QCOMPARE(next.watchTables().at(0)->model()->items(), saved);
        }

        // A broken file is refused with the place of the problem; the tables stay.
        QFile bad(dir.filePath(QStringLiteral("bad.json")));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write(
            R"({"format":"fatek-studio-watchlist","version":1,"tables":[{"name":"A","items":[{"address":"R1"},{"address":"Q5"}]}]})");
        bad.close();
        const Status refused = window.loadWatchList(bad.fileName());
        QVERIFY(!refused.ok());
        QVERIFY2(QString::fromStdString(refused.error().text()).contains(QStringLiteral("item 2")),
                 refused.error().text().c_str());
        QCOMPARE(window.watchTables().size(), 2);
    }

    void operatorModeRefusesWrites()
    {
        Plc plc;
        plc.plc.setValue(addr("R100"), 5);
        MainWindow window(true);
        window.setConfirmHandler([](QWidget *, const QString &) { return true; });
        window.show();
        auto *mode = window.findChild<QLabel *>(QStringLiteral("modeLabel"));
        QVERIFY(mode);
        QVERIFY(mode->isVisible());
        QCOMPARE(mode->text(), QStringLiteral("Operator mode (read-only)"));
        Connection *c = connect(window, plc);
        QVERIFY(c->session()->isReadOnly());
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        WatchTableWidget *table = window.currentWatchTable();
        typeInto(table->addressEdit(), QStringLiteral("R100"));
        QTRY_VERIFY_WITH_TIMEOUT(table->model()->hasValue(0), longWait);
        table->model()->setData(table->model()->index(0, WatchTableModel::ValueColumn),
                                QStringLiteral("6"));
        QTRY_VERIFY_WITH_TIMEOUT(table->message().contains(QStringLiteral("failed")), longWait);
        QVERIFY2(table->message().contains(QStringLiteral("read-only"), Qt::CaseInsensitive)
                     || table->message().contains(QStringLiteral("operator"), Qt::CaseInsensitive),
                 qPrintable(table->message()));
        QCOMPARE(plc.plc.value(addr("R100")).value_or(0), 5u);
    }

    void connectionDialogRoundTripAndRecent()
    {
        SavedConnection serial;
        serial.name = QStringLiteral("Line 2");
        serial.settings = LinkSettings::serial(QStringLiteral("/dev/ttyUSB7"), 19200,
                                               LinkSettings::ProtocolChoice::Auto);
        serial.settings.parity = LinkSettings::Parity::Odd;
        serial.settings.dataBits = 8;
        serial.settings.stopBits = 2;
        serial.settings.timeoutMs = 700;
        serial.settings.retries = 4;
        serial.station = 12;
        ConnectionDialog dialog({});
        dialog.setConnection(serial);
        QCOMPARE(dialog.connection(), serial);

        SavedConnection udp;
        udp.name = QStringLiteral("Remote");
        udp.settings = LinkSettings::udp(QStringLiteral("10.0.0.9"), 5000,
                                         LinkSettings::ProtocolChoice::Binary);
        dialog.setConnection(udp);
        QCOMPARE(dialog.connection(), udp);

        // Connections that came up are remembered, most recent first, across windows
        // (QSettings), with the station; one that never connected (no such port) is not.
        Plc plc;
        SavedConnection tcp = savedFor(plc.port);
        tcp.name = QStringLiteral("Line 3");
        tcp.station = 12;
        plc.server.setStation(12);
        {
            MainWindow window;
            Connection *failing = window.openConnection(serial);
            Connection *working = window.openConnection(tcp);
            QTRY_COMPARE_WITH_TIMEOUT(working->linkState(), LinkState::Connected, longWait);
            QTRY_VERIFY_WITH_TIMEOUT(failing->linkFailures() > 0, longWait);
            QCOMPARE(window.connections()->connections().size(), 2);
            auto *menu = window.findChild<QMenu *>(QStringLiteral("recentMenu"));
            QVERIFY(menu);
            QStringList labels;
            for (QAction *a : menu->actions())
                labels << a->text();
            QVERIFY2(labels.join(u'|').contains(QStringLiteral("station 12")),
                     qPrintable(labels.join(u'|')));
        }
        MainWindow window;
        const QList<SavedConnection> recent = window.connections()->recent();
        QVERIFY(!recent.isEmpty());
        QCOMPARE(recent.at(0), tcp);
        QVERIFY(!recent.contains(serial));
    }

    void toolsFollowTheCurrentConnection()
    {
        MainWindow window;
        for (const char *name : {"plcControlDock", "forcingDock", "rawConsoleDock"}) {
            auto *dock = window.findChild<QDockWidget *>(QLatin1String(name));
            QVERIFY2(dock && dock->widget(), name);
        }
        QVERIFY(window.findChild<QDockWidget *>(QStringLiteral("connectionsDock")));
    }

    void demoTableMoves()
    {
        MainWindow window;
        window.show();
        QSignalSpy ready(&window, &MainWindow::demoReady);
        window.startDemo();
        QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, longWait);
        WatchTableWidget *table = window.currentWatchTable();
        WatchTableModel *model = table->model();
        QCOMPARE(model->items(), DemoSimulator::demoTable().items);
        const int counter = rowOf(model, "R0");
        QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(counter), longWait);
        const QString first = model->valueText(counter);
        QTRY_VERIFY_WITH_TIMEOUT(model->valueText(counter) != first, longWait);
        QVERIFY(window.hasValues());
    }

    void quitWithQueuedWrites_data()
    {
        QTest::addColumn<QString>("button");
        QTest::newRow("wait") << QStringLiteral("waitButton");
        QTest::newRow("drop") << QStringLiteral("dropButton");
    }

    // Quitting while writes wait for a slow PLC: the window says so; Wait sends them all before
    // it closes, Drop closes at once and they never reach the PLC.
    void quitWithQueuedWrites()
    {
        QFETCH(QString, button);
        Plc plc;
        FaultConfig slow;
        slow.latencyMs = 150;
        plc.server.setFaults(slow);
        MainWindow window;
        window.show();
        Connection *c = connect(window, plc);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        for (std::uint32_t i = 0; i < 4; ++i)
            c->session()->submit(Request::writeRegisters(1, addr("R100").advanced(i), {i + 1}));
        QTRY_VERIFY_WITH_TIMEOUT(c->session()->pendingWrites() > 0, longWait);

        // The question is modal (its own event loop): click the real button once it shows.
        QString question;
        QTimer clicker;
        clicker.setInterval(10);
        QObject::connect(&clicker, &QTimer::timeout, &clicker, [&] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            if (!box || box->objectName() != QLatin1String("pendingWritesBox"))
                return;
            auto *target = box->findChild<QPushButton *>(button);
            if (!target)
                return;
            question = box->text() + QLatin1Char(' ') + box->informativeText();
            clicker.stop();
            QTest::mouseClick(target, Qt::LeftButton);
        });
        clicker.start();
        window.close();
        clicker.stop();
        QVERIFY2(question.contains(QStringLiteral("not been sent")), qPrintable(question));

        if (button == QLatin1String("waitButton")) {
            QVERIFY(window.isVisible()); // it closes when the links have drained
            QTRY_VERIFY_WITH_TIMEOUT(!window.isVisible(), longWait);
            for (std::uint32_t i = 0; i < 4; ++i)
                QCOMPARE(plc.plc.value(addr("R100").advanced(i)).value_or(0), i + 1);
        } else {
            QVERIFY(!window.isVisible());
            QTRY_COMPARE_WITH_TIMEOUT(c->session()->pendingWrites(), 0, longWait);
            QCOMPARE(plc.plc.value(addr("R103")).value_or(0), 0u);
        }
        QCOMPARE(c->session()->pendingWrites(), 0);
    }
};

QTEST_MAIN(TestUiMainWindow)
#include "tst_ui_mainwindow.moc"
