// What an engineer notices on the first day with the real main window (issue 16, minors), done as
// a person does it against simulated PLCs over loopback TCP: Enter on a confirmation, switching
// table tabs with the mouse, messages that must not move the rows, quitting with unsaved work,
// shortcuts, a refused port, the raw console's questions and operator mode.
// What reached a PLC is checked on the simulator's side of the wire.
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"
#include "ui/common/messageline.h"
#include "ui/connection/connection.h"
#include "ui/connection/connectiondialog.h"
#include "ui/connection/connectionlistmodel.h"
#include "ui/connection/connectionmanager.h"
#include "ui/connection/stationscandialog.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/tools/forcingpanel.h"
#include "ui/tools/rawconsole.h"
#include "ui/tools/rawsendbar.h"
#include "ui/watch/watchtablemodel.h"
#include "uitestutil.h"

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabBar>
#include <QTabWidget>
#include <QTableView>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <functional>

using namespace Fatek;
using UiTestUtil::answerModal;
using UiTestUtil::clickButton;

namespace {

constexpr int longWait = 20000;
constexpr int keyDelayMs = 150; // a person types a few characters a second

Address addr(const char *text)
{
    return *Address::parse(text);
}

// A simulated FBs on a free loopback port (or a given one), logging what it executes.
struct Plc
{
    SimulatedPlc plc{ModelProfile::fbs()};
    SimServer server{&plc};
    QStringList log;
    quint16 port = 0;

    explicit Plc(quint16 wanted = 0)
    {
        server.setVerbose(true);
        QObject::connect(&server, &SimServer::logLine, &server,
                         [this](const QString &line) { log << line; });
        QString error;
        if (server.listenTcp(wanted, &error))
            port = server.tcpPort();
        else
            qWarning("cannot listen: %s", qPrintable(error));
    }
    int writesLogged() const
    {
        int n = 0;
        for (const QString &line : log)
            n += line.contains(QStringLiteral("write")) ? 1 : 0;
        return n;
    }
};

SavedConnection savedFor(quint16 port, const QString &name = QStringLiteral("Test PLC"))
{
    SavedConnection saved;
    saved.name = name;
    saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), port);
    saved.settings.timeoutMs = 300;
    saved.settings.retries = 0;
    saved.station = 1;
    return saved;
}

void typeSlowly(QWidget *widget, const QString &text)
{
    for (const QChar ch : text)
        QTest::keyClicks(widget, QString(ch), Qt::NoModifier, keyDelayMs);
}

// Whether a line edit shows all its text: it fits with room for the frame and the inner margins
// (about 6 px a side in the Fusion style), so nothing is scrolled out.
bool urlShownWhole(const QLineEdit *line)
{
    return line->fontMetrics().horizontalAdvance(line->text()) <= line->width() - 12;
}

} // namespace

class TestUiDayOne : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_dayone"));
    }

    // Type a value, Enter, and Enter again on the question: the second Enter must not write
    // (the safe answer is the default, as for RUN/STOP and forcing).
    void secondEnterDoesNotWrite()
    {
        Plc plc;
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        Connection *c = window.openConnection(savedFor(plc.port), false);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        WatchTableWidget *table = window.currentWatchTable();
        QVERIFY(table->confirmWrites());
        typeSlowly(table->addressEdit(), QStringLiteral("R100"));
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(0), longWait);

        QTableView *view = table->view();
        const QModelIndex value = table->viewIndex(model->index(0, WatchTableModel::ValueColumn));
        view->setFocus();
        view->setCurrentIndex(value);
        QTest::keyClick(view->viewport(), Qt::Key_F2);
        auto *editor = view->viewport()->findChild<QLineEdit *>();
        QVERIFY(editor);
        editor->selectAll();
        typeSlowly(editor, QStringLiteral("55"));
        const QString question
            = answerModal([&] { QTest::keyClick(editor, Qt::Key_Return); },
                          [](QWidget *modal) { QTest::keyClick(modal, Qt::Key_Return); });
        QVERIFY2(question.contains(QStringLiteral("R100")), qPrintable(question));
        QTRY_VERIFY_WITH_TIMEOUT(table->message().contains(QStringLiteral("cancelled")), longWait);
        QTest::qWait(2 * 300);
        QCOMPARE(plc.writesLogged(), 0);
        QCOMPARE(plc.plc.value(addr("R100")).value_or(0), 0u);
    }

    // A timer's contact comes with its current value: typing T0 adds RT0 beside it, and both
    // are read from the PLC.
    void timerComesWithItsCurrentValue()
    {
        Plc plc;
        QVERIFY(plc.plc.setValue(addr("RT0"), 123));
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        Connection *c = window.openConnection(savedFor(plc.port), false);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        WatchTableWidget *table = window.currentWatchTable();
        typeSlowly(table->addressEdit(), QStringLiteral("T0 C5 RC5"));
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        WatchTableModel *model = table->model();
        QStringList rows;
        for (int r = 0; r < model->rowCount(); ++r)
            rows << QString::fromStdString(model->item(r).address.toString());
        QCOMPARE(rows, QStringList({"T0", "RT0", "C5", "RC5"}));
        QVERIFY2(table->message().contains(QStringLiteral("RT/RC")), qPrintable(table->message()));
        QTRY_COMPARE_WITH_TIMEOUT(model->valueText(1), QStringLiteral("123"), longWait);
    }

    // Two tables on two PLCs: clicking a table's tab makes the tools act on that table's PLC.
    void toolsFollowTheTableInFront()
    {
        Plc first;
        Plc second;
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        Connection *a
            = window.openConnection(savedFor(first.port, QStringLiteral("Press 1")), false);
        WatchTableWidget *tableA = window.currentWatchTable();
        tableA->setConnection(a);
        Connection *b
            = window.openConnection(savedFor(second.port, QStringLiteral("Press 2")), false);
        WatchTableWidget *tableB = window.addWatchTable(QStringLiteral("Second"));
        tableB->setConnection(b);
        window.openTool(QStringLiteral("control"));
        auto *target = window.findChild<QLabel *>(QStringLiteral("targetLabel"));
        QVERIFY(target);

        auto *tabs = window.findChild<QTabWidget *>(QStringLiteral("watchTabs"));
        QTabBar *bar = tabs->tabBar();
        // The second table is behind: its tab first, then back to the first one.
        for (int round = 0; round < 2; ++round) {
            QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(1).center());
            QTRY_COMPARE(window.currentWatchTable(), tableB);
            QCOMPARE(window.currentConnection(), b);
            QTRY_VERIFY2(target->text().contains(QStringLiteral("Press 2")),
                         qPrintable(target->text()));
            QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(0).center());
            QTRY_COMPARE(window.currentWatchTable(), tableA);
            QCOMPARE(window.currentConnection(), a);
            QTRY_VERIFY2(target->text().contains(QStringLiteral("Press 1")),
                         qPrintable(target->text()));
            QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(1).center());
            QTRY_COMPARE(window.currentWatchTable(), tableB);
            QCOMPARE(window.currentConnection(), b);
            QTRY_VERIFY2(target->text().contains(QStringLiteral("Press 2")),
                         qPrintable(target->text()));
        }
    }

    // The Connections panel names the PLC as printed on the unit and shows RUN/STOP, and
    // follows a change of RUN/STOP made elsewhere (at the PLC's own switch, say).
    void connectionsPanelShowsModelAndRunStop()
    {
        Plc plc;
        plc.plc.setRunning(false);
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        Connection *c = window.openConnection(savedFor(plc.port), false);
        QTRY_COMPARE_WITH_TIMEOUT(c->plcText(), QStringLiteral("FBs-28MC · STOP"), longWait);
        auto *view = window.findChild<QTableView *>(QStringLiteral("connectionsView"));
        QVERIFY(view);
        const QModelIndex cell = view->model()->index(0, ConnectionListModel::PlcColumn);
        QCOMPARE(cell.data().toString(), QStringLiteral("FBs-28MC · STOP"));
        plc.plc.setRunning(true);
        QTRY_COMPARE_WITH_TIMEOUT(cell.data().toString(), QStringLiteral("FBs-28MC · RUN"),
                                  3 * Connection::plcStatusIntervalMs);
        // The link goes down: RUN/STOP is unknown, not the last thing seen.
        plc.server.close();
        QTRY_VERIFY_WITH_TIMEOUT(!cell.data().toString().contains(QStringLiteral("RUN")), longWait);
    }

    // Tools > Scan Stations finds the PLC on station 7 of the link, and Use Station makes the
    // connection talk to it; the empty addresses the scan asked do not count as silent stations.
    void stationScanFindsAndUsesAStation()
    {
        Plc plc;
        plc.server.setStation(7);
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        Connection *c = window.openConnection(savedFor(plc.port), false);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        auto *scan = window.findChild<QAction *>(QStringLiteral("scanStationsAction"));
        QVERIFY(scan);
        scan->trigger();
        auto *dialog = window.findChild<StationScanDialog *>(QStringLiteral("stationScanDialog"));
        QVERIFY(dialog);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isScanning(), longWait);
        QCOMPARE(dialog->foundStations(), QList<int>{7});
        auto *use = dialog->findChild<QPushButton *>(QStringLiteral("useStationButton"));
        QVERIFY(use && use->isEnabled());
        QTest::mouseClick(use, Qt::LeftButton);
        QCOMPARE(c->station(), quint8(7));
        QTRY_VERIFY_WITH_TIMEOUT(c->plcText().startsWith(QStringLiteral("FBs-28MC")), longWait);
        QVERIFY(c->silentStations().isEmpty());
        QVERIFY2(!c->stateText().contains(QStringLiteral("no answer")), qPrintable(c->stateText()));
    }

    // A message that comes (a typing mistake) and goes must not move the rows under the pointer.
    void messagesDoNotMoveTheRows()
    {
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        WatchTableWidget *table = window.currentWatchTable();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const int rowsTop = table->view()->mapTo(&window, QPoint(0, 0)).y();
        typeSlowly(table->addressEdit(), QStringLiteral("R99999"));
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        QVERIFY(!table->message().isEmpty());
        QApplication::processEvents();
        QCOMPARE(table->view()->mapTo(&window, QPoint(0, 0)).y(), rowsTop);
        // The line shows the message, elided if it must be, with all of it in the tooltip.
        auto *line = table->findChild<MessageLine *>(QStringLiteral("messageLabel"));
        QVERIFY(line);
        QVERIFY(line->isError());
        QCOMPARE(line->shownLines().size(), 1);
        QCOMPARE(line->toolTip(), table->message());

        // The forcing panel's buttons stay put too while its outcome line changes.
        auto *forcing = qobject_cast<ForcingPanel *>(window.openTool(QStringLiteral("forcing")));
        QVERIFY(forcing);
        QTest::qWait(100);
        auto *button = forcing->findChild<QPushButton *>(QStringLiteral("disableButton"));
        QVERIFY(button);
        auto *message = forcing->findChild<MessageLine *>(QStringLiteral("forcingMessage"));
        QVERIFY(message);
        const QPoint before = button->mapTo(&window, QPoint(0, 0));
        message->setMessage(QStringLiteral("A long outcome that needs more than one line in a "
                                           "narrow dock: the PLC refused the request because the "
                                           "address is outside of what this model has."),
                            true);
        QApplication::processEvents();
        QCOMPARE(button->mapTo(&window, QPoint(0, 0)), before);
        message->clear();
        QApplication::processEvents();
        QCOMPARE(button->mapTo(&window, QPoint(0, 0)), before);
    }

    // Quit with a table that was never saved asks, as editors do; Cancel keeps everything.
    void quitAsksAboutUnsavedTablesAndLogging()
    {
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        // Nothing changed: Ctrl+Q quits at once.
        QTest::keyClick(&window, Qt::Key_Q, Qt::ControlModifier);
        QTRY_VERIFY(!window.isVisible());

        window.show();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        WatchTableWidget *table = window.currentWatchTable();
        typeSlowly(table->addressEdit(), QStringLiteral("R0 R1"));
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        QCOMPARE(table->model()->rowCount(), 2);
        QString question
            = answerModal([&] { QTest::keyClick(&window, Qt::Key_Q, Qt::ControlModifier); },
                          clickButton("cancelButton"));
        QVERIFY2(question.contains(QStringLiteral("not saved")), qPrintable(question));
        QVERIFY(window.isVisible());
        QCOMPARE(table->model()->rowCount(), 2);

        // Saved: no question about the table; a running log is still worth one.
        const QString list = m_settingsDir.filePath(QStringLiteral("dayone.json"));
        QVERIFY(window.saveWatchList(list));
        QVERIFY(window.windowTitle().contains(QStringLiteral("dayone.json")));
        QVERIFY(!window.windowTitle().contains(QStringLiteral("FATEK Studio")));
        QVERIFY(window.startLogging(m_settingsDir.filePath(QStringLiteral("dayone.csv"))));
        question = answerModal([&] { window.close(); }, clickButton("cancelButton"));
        QVERIFY2(question.contains(QStringLiteral("logging")), qPrintable(question));
        QVERIFY(window.isVisible());
        question = answerModal([&] { window.close(); }, clickButton("quitButton"));
        QVERIFY2(question.contains(QStringLiteral("logging")), qPrintable(question));
        QTRY_VERIFY(!window.isVisible());
    }

    // Ctrl+Shift+R on a console that is open behind the Connections tab brings it to the front
    // (it used to hide it); pressed again when it is in front, it hides it.
    void consoleShortcutRaisesATabbedConsole()
    {
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto *console = window.findChild<QDockWidget *>(QStringLiteral("rawConsoleDock"));
        QVERIFY(console);
        QVERIFY(!console->isHidden());
        QVERIFY(console->visibleRegion().isEmpty() || !console->isVisible()); // behind a tab
        QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY(console->isVisible() && !console->visibleRegion().isEmpty());
        QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY(console->isHidden());
        QTest::keyClick(&window, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY(console->isVisible() && !console->visibleRegion().isEmpty());
    }

    // A refused port: the status line says the attempts failed (no "RTT 0.0 ms", no "0
    // errors"), Recent stays clean, and Reconnect Now (F5) tries at once instead of after the
    // backoff.
    void refusedPortSaysSoAndReconnectsNow()
    {
        quint16 port = 0;
        {
            QTcpServer probe;
            QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
            port = probe.serverPort();
        } // closed: connecting there is refused
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        SavedConnection saved = savedFor(port, QStringLiteral("Press 9"));
        saved.settings.reconnectMinMs = 60000; // only F5 can make a second attempt in this test
        saved.settings.reconnectMaxMs = 60000;
        Connection *c = window.openConnection(saved);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Reconnecting, longWait);
        auto *status = window.findChild<QLabel *>(QStringLiteral("linkStatus"));
        QVERIFY(status);
        QTRY_VERIFY2(status->text().contains(QStringLiteral("1 failed attempt")),
                     qPrintable(status->text()));
        QVERIFY2(!status->text().contains(QStringLiteral("RTT")), qPrintable(status->text()));
        QVERIFY(c->errorCount() >= 1);
        for (const SavedConnection &r : window.connections()->recent())
            QVERIFY(r.name != QLatin1String("Press 9"));

        auto *reconnect = window.findChild<QAction *>(QStringLiteral("reconnectNowAction"));
        QVERIFY(reconnect);
        QVERIFY(reconnect->isEnabled());
        QTest::keyClick(&window, Qt::Key_F5);
        QTRY_VERIFY2_WITH_TIMEOUT(status->text().contains(QStringLiteral("2 failed attempt")),
                                  qPrintable(status->text()), 5000);

        // The PLC is back on that port: F5 connects now, and now it is worth remembering.
        Plc plc(port);
        QCOMPARE(plc.port, port);
        QTest::keyClick(&window, Qt::Key_F5);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, 5000);
        auto remembered = [&window] {
            for (const SavedConnection &r : window.connections()->recent()) {
                if (r.name == QLatin1String("Press 9"))
                    return true;
            }
            return false;
        };
        QTRY_VERIFY(remembered());
        QVERIFY(!reconnect->isEnabled());
    }

    // The raw console names the command it asks about, and in operator mode it refuses without
    // asking first.
    // Issue 32: the connection dialog takes the link as a URL (as fatek-cli --link does): typed,
    // it fills the fields; a bad one is refused with the reason and nothing connects; the
    // recent entry and the Connections list show the URL to copy into a script.
    // Every kind of link's rows line up with the rest of the form (the TCP page's Host and Port
    // used to sit 21 px left of the others, in a form of their own), and only the chosen kind's
    // rows show.
    void connectionDialogFieldsLineUp()
    {
        MainWindow window;
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QStringList seen;
        answerModal(
            [&] { QTest::keyClick(&window, Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier); },
            [&](QWidget *widget) {
                auto *dialog = qobject_cast<ConnectionDialog *>(widget);
                QVERIFY(dialog);
                auto *kind = dialog->findChild<QComboBox *>(QStringLiteral("linkKindCombo"));
                auto *name = dialog->findChild<QLineEdit *>(QStringLiteral("connectionNameEdit"));
                QVERIFY(kind && name);
                // Home, then Down through the list, as a user steps through the combo's kinds.
                QTest::mouseClick(name, Qt::LeftButton);
                QTest::keyClick(name, Qt::Key_Tab); // to the Link combo
                QCOMPARE(QApplication::focusWidget(), kind);
                QTest::keyClick(kind, Qt::Key_Home);
                for (int i = 0; i < kind->count(); ++i) {
                    if (i > 0)
                        QTest::keyClick(kind, Qt::Key_Down);
                    QCOMPARE(kind->currentIndex(), i);
                    QTest::qWait(50);
                    auto *form = qobject_cast<QFormLayout *>(dialog->layout()->itemAt(0)->layout());
                    QVERIFY(form);
                    QStringList labels;
                    for (int row = 0; row < form->rowCount(); ++row) {
                        QLayoutItem *label = form->itemAt(row, QFormLayout::LabelRole);
                        QLayoutItem *field = form->itemAt(row, QFormLayout::FieldRole);
                        if (!label || !field || !label->widget() || !label->widget()->isVisible())
                            continue;
                        labels << qobject_cast<QLabel *>(label->widget())->text();
                        QCOMPARE(field->geometry().left(), name->geometry().left());
                    }
                    seen << labels.join(u',');
                }
                QTest::keyClick(dialog, Qt::Key_Escape);
            });
        QCOMPARE(seen.size(), 4);
        // Serial: its port and framing, no host; TCP and UDP: host and port; the gateway: its
        // broker.
        QVERIFY2(seen[0].contains(QLatin1String("&Baud rate:"))
                     && !seen[0].contains(QLatin1String("&Host:")),
                 qPrintable(seen[0]));
        for (int tcpOrUdp : {1, 2}) {
            QVERIFY2(seen[tcpOrUdp].contains(QLatin1String("&Host:"))
                         && !seen[tcpOrUdp].contains(QLatin1String("&Baud rate:"))
                         && !seen[tcpOrUdp].contains(QLatin1String("&Broker:")),
                     qPrintable(seen[tcpOrUdp]));
        }
        QVERIFY2(seen[3].contains(QLatin1String("&Broker:"))
                     && !seen[3].contains(QLatin1String("&Host:"))
                     && !seen[3].contains(QLatin1String("Pro&tocol:")),
                 qPrintable(seen[3]));
    }

    void connectionDialogTakesAUrl()
    {
        Plc plc;
        plc.server.setStation(3);
        MainWindow window;
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QString url
            = QStringLiteral("tcp://127.0.0.1:%1?protocol=facon&station=3&timeout=400")
                  .arg(plc.port);
        QString refusal;
        SavedConnection filled;
        answerModal(
            [&] { QTest::keyClick(&window, Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier); },
            [&](QWidget *widget) {
                auto *dialog = qobject_cast<ConnectionDialog *>(widget);
                QVERIFY(dialog);
                auto *name = dialog->findChild<QLineEdit *>(QStringLiteral("connectionNameEdit"));
                name->selectAll();
                typeSlowly(name, QStringLiteral("By URL"));
                auto *line = dialog->findChild<QLineEdit *>(QStringLiteral("linkUrlEdit"));
                QVERIFY(line && line->isVisible());
                // The whole default URL is readable, not its tail only.
                QVERIFY2(urlShownWhole(line), qPrintable(line->text()));
                // First a port that cannot be: refused, the dialog stays.
                QTest::mouseClick(line, Qt::LeftButton);
                line->selectAll();
                typeSlowly(line, QStringLiteral("tcp://127.0.0.1:99999"));
                auto *connect = dialog->findChild<QPushButton *>(QStringLiteral("connectButton"));
                QTest::mouseClick(connect, Qt::LeftButton);
                auto *problem = dialog->findChild<QLabel *>(QStringLiteral("connectionErrorLabel"));
                QVERIFY(dialog->isVisible() && problem->isVisible());
                refusal = problem->text();
                // Then the right one: Tab takes it into the fields.
                QTest::mouseClick(line, Qt::LeftButton);
                line->selectAll();
                typeSlowly(line, url);
                QTest::keyClick(line, Qt::Key_Tab);
                filled = dialog->connection();
                QVERIFY(!problem->isVisible());
                QVERIFY2(urlShownWhole(line), qPrintable(line->text()));
                QTest::mouseClick(connect, Qt::LeftButton);
            });
        QVERIFY2(refusal.contains(QStringLiteral("99999")), qPrintable(refusal));
        QCOMPARE(filled.settings.kind, LinkSettings::Kind::Tcp);
        QCOMPARE(filled.settings.port, plc.port);
        QCOMPARE(filled.settings.protocol, LinkSettings::ProtocolChoice::Facon);
        QCOMPARE(filled.settings.timeoutMs, 400);
        QCOMPARE(int(filled.station), 3);
        Connection *c = window.connections()->find(QStringLiteral("By URL"));
        QVERIFY(c);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        QCOMPARE(int(c->station()), 3);

        // The URL reads back from the Connections list and the recent entry.
        const QString shown = c->saved().settings.toUrl(c->station());
        Message error;
        const std::optional<LinkSettings::Parsed> back = LinkSettings::fromUrl(shown, &error);
        QVERIFY(back);
        QCOMPARE(back->settings, c->saved().settings);
        auto *list = window.findChild<ConnectionListModel *>();
        QVERIFY(list);
        const QString tip
            = list->data(list->index(0, ConnectionListModel::LinkColumn), Qt::ToolTipRole)
                  .toString();
        QVERIFY2(tip.contains(QStringLiteral("URL: ") + shown), qPrintable(tip));
        auto *recent = window.findChild<QMenu *>(QStringLiteral("recentMenu"));
        QVERIFY(recent);
        QTRY_VERIFY_WITH_TIMEOUT(!recent->actions().isEmpty(), longWait);
        QCOMPARE(recent->actions().first()->toolTip(), shown);
    }

    void rawConsoleQuestionsAndOperatorMode()
    {
        Plc plc;
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        Connection *c = window.openConnection(savedFor(plc.port), false);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        auto *console = qobject_cast<RawConsole *>(window.openTool(QStringLiteral("console")));
        QVERIFY(console);
        RawSendBar *bar = console->sendBar();
        QStringList questions;
        bar->setConfirmer([&](const QString &q) {
            questions << q;
            return false;
        });
        bar->setMode(RawSendBar::Mode::Ascii);
        bar->setAddFraming(true);
        bar->setText(QStringLiteral("01410"));
        auto *send = bar->findChild<QPushButton *>(QStringLiteral("sendButton"));
        QVERIFY(send);
        QTest::mouseClick(send, Qt::LeftButton);
        QCOMPARE(questions.size(), 1);
        QVERIFY2(questions.first().contains(QStringLiteral("RUN/STOP")),
                 qPrintable(questions.first()));

        // Operator mode: no question, the session's refusal, nothing on the wire.
        c->session()->setReadOnly(true);
        auto runStopFrames = [&plc] {
            return plc.log.filter(QStringLiteral("RUN/STOP")).size();
        };
        const qsizetype before = runStopFrames();
        QTest::mouseClick(send, Qt::LeftButton);
        QCOMPARE(questions.size(), 1);
        QTRY_VERIFY2(
            bar->resultText().contains(QStringLiteral("read-only"), Qt::CaseInsensitive)
                || bar->resultText().contains(QStringLiteral("operator"), Qt::CaseInsensitive),
            qPrintable(bar->resultText()));
        QTest::qWait(300);
        QCOMPARE(runStopFrames(), before);

        // The write dialog does not open in operator mode either.
        WatchTableWidget *table = window.currentWatchTable();
        table->setConnection(c);
        typeSlowly(table->addressEdit(), QStringLiteral("R5"));
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        table->view()->setFocus();
        table->view()->setCurrentIndex(
            table->viewIndex(table->model()->index(0, WatchTableModel::ValueColumn)));
        QTimer escape; // should a dialog open anyway, close it so the failure is reported
        bool dialogOpened = false;
        escape.setInterval(50);
        connect(&escape, &QTimer::timeout, &escape, [&] {
            if (QWidget *modal = QApplication::activeModalWidget()) {
                dialogOpened = true;
                QTest::keyClick(modal, Qt::Key_Escape);
            }
        });
        escape.start();
        QTest::keyClick(table->view(), Qt::Key_W, Qt::ControlModifier);
        escape.stop();
        QVERIFY(!dialogOpened);
        QVERIFY2(table->message().contains(QStringLiteral("Operator mode")),
                 qPrintable(table->message()));
    }
};

QTEST_MAIN(TestUiDayOne)
#include "tst_ui_dayone.moc"
