// A person at a laptop with the real main window and a simulated FBs running the demo ladder (R1 a
// sine, Y0 blinking) over loopback TCP: typing into the table's own editor while values change,
// choosing a format with the mouse, forced points marked in the table, a wrong station number.
// What reached the PLC is counted on the simulator's side of the wire (its request log).
#include "core/sim/faultconfig.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"
#include "ui/common/uitext.h"
#include "ui/connection/connection.h"
#include "ui/connection/connectionlistmodel.h"
#include "ui/connection/connectionmanager.h"
#include "ui/connection/connectionspanel.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/watch/watchtablemodel.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPointer>
#include <QProgressBar>
#include <QScopeGuard>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;

namespace {

constexpr int longWait = 20000;
// A person types about 5 characters a second and needs a moment to aim the mouse.
constexpr int keyDelayMs = 200;
constexpr int mouseDelayMs = 500;

Address addr(const char *text)
{
    return *Address::parse(text);
}

// The demo PLC (FBs, RUN, demo ladder) on a free loopback port, logging every request it executes.
struct DemoPlc
{
    SimulatedPlc plc{ModelProfile::fbs()};
    SimServer server{&plc};
    QStringList log;
    quint16 port = 0;

    DemoPlc()
    {
        plc.setRunning(true);
        server.setVerbose(true);
        QObject::connect(&server, &SimServer::logLine, &server,
                         [this](const QString &line) { log << line; });
        QString error;
        if (server.listenTcp(0, &error))
            port = server.tcpPort();
        else
            qWarning("cannot listen: %s", qPrintable(error));
        server.setDemoLadder(true);
    }
    qsizetype count(const QString &needle) const
    {
        qsizetype n = 0;
        for (const QString &line : log)
            n += line.contains(needle) ? 1 : 0;
        return n;
    }
};

SavedConnection savedFor(quint16 port, quint8 station = 1)
{
    SavedConnection saved;
    saved.name = QStringLiteral("Bench PLC");
    saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), port);
    saved.settings.timeoutMs = 300;
    saved.settings.retries = 1;
    saved.station = station;
    return saved;
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

class TestUiLiveTable : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;
    std::unique_ptr<MainWindow> m_window;
    QStringList m_questions;

    // The window at a laptop's size, connected to `port`, with `items` typed into its first table.
    WatchTableWidget *openTable(quint16 port, const QString &items, quint8 station = 1,
                                LinkSettings::ProtocolChoice protocol
                                = LinkSettings::ProtocolChoice::Facon)
    {
        m_window = std::make_unique<MainWindow>();
        m_window->setConfirmHandler([this](QWidget *, const QString &question) {
            m_questions << question;
            return true;
        });
        m_window->resize(1366, 768);
        m_window->show();
        if (!QTest::qWaitForWindowExposed(m_window.get()))
            return nullptr;
        SavedConnection saved = savedFor(port, station);
        saved.settings.protocol = protocol;
        Connection *c = m_window->openConnection(saved, false);
        if (!QTest::qWaitFor([c] { return c->linkState() == LinkState::Connected; }, longWait))
            return nullptr;
        WatchTableWidget *table = m_window->currentWatchTable();
        QLineEdit *edit = table->addressEdit();
        QTest::mouseClick(edit, Qt::LeftButton);
        QTest::keyClicks(edit, items);
        QTest::keyClick(edit, Qt::Key_Return);
        return table;
    }

    // Through the window system, as a real double-click arrives (the widget overload of
    // QTest::mouseDClick bypasses the double-click detection and the view never edits).
    static void doubleClick(QAbstractItemView *view, const QModelIndex &index)
    {
        QWidget *top = view->window();
        const QPoint pos = view->viewport()->mapTo(top, view->visualRect(index).center());
        QTest::mouseMove(top->windowHandle(), pos, mouseDelayMs);
        QTest::mouseDClick(top->windowHandle(), Qt::LeftButton, {}, pos);
    }

    // Waits until `n` more poll batches have reached the window.
    static bool waitForPolls(QSignalSpy &batches, int n)
    {
        const qsizetype target = batches.count() + n;
        return QTest::qWaitFor([&] { return batches.count() >= target; }, longWait);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_livetable"));
    }

    void cleanup()
    {
        m_window.reset();
        m_questions.clear();
    }

    // Issue 16.5: with every tool open the window still fits a 1366x768 laptop, and 1920x1080 at
    // 150 % (1280x720 logical), title bar and task bar taken off; also with a 1.5x larger font.
    void windowFitsALaptop_data()
    {
        QTest::addColumn<double>("fontScale");
        QTest::addColumn<QSize>("screen");
        QTest::newRow("1366x768") << 1.0 << QSize(1366, 768);
        QTest::newRow("1920x1080 at 150 %") << 1.0 << QSize(1280, 720);
        QTest::newRow("larger system font") << 1.5 << QSize(1366, 768);
    }
    void windowFitsALaptop()
    {
        QFETCH(double, fontScale);
        QFETCH(QSize, screen);
        const QFont original = QApplication::font();
        QFont font = original;
        font.setPointSizeF(font.pointSizeF() * fontScale);
        QApplication::setFont(font);
        const auto restore = qScopeGuard([&original] { QApplication::setFont(original); });
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        for (const char *tool : {"control", "forcing", "console", "trend"})
            QVERIFY2(m_window->openTool(QString::fromLatin1(tool)), tool);
        const QSize usable = screen - QSize(0, 70); // title bar and task bar
        m_window->resize(usable);
        QTRY_COMPARE(m_window->size(), usable);
        const QSize minimum = m_window->minimumSizeHint().expandedTo(m_window->minimumSize());
        qInfo("minimum %dx%d", minimum.width(), minimum.height());
        QVERIFY2(minimum.width() <= usable.width() && minimum.height() <= usable.height(),
                 qPrintable(QStringLiteral("%1x%2").arg(minimum.width()).arg(minimum.height())));
        // Every tool dock is on screen, none squeezed to nothing.
        for (QDockWidget *dock : m_window->findChildren<QDockWidget *>()) {
            // A tab behind another tab in the same group is not on screen by design.
            if (!dock->isVisible()
                || (dock->visibleRegion().isEmpty()
                    && !m_window->tabifiedDockWidgets(dock).isEmpty()))
                continue;
            QVERIFY2(m_window->rect().contains(dock->geometry()), qPrintable(dock->objectName()));
            QVERIFY2(dock->width() > 100 && dock->height() > 60, qPrintable(dock->objectName()));
        }
    }

    // Issue 16.1: double-click the sine's value, type 55 at a person's pace while polls come,
    // Enter.
    void typedValueSurvivesPolling()
    {
        DemoPlc plc;
        QVERIFY(plc.port != 0);
        WatchTableWidget *table = openTable(plc.port, QStringLiteral("R1"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(0), longWait);
        QSignalSpy batches(table->connection(), &Connection::itemValues);

        QTableView *view = table->view();
        const QModelIndex value = table->viewIndex(model->index(0, WatchTableModel::ValueColumn));
        doubleClick(view, value);
        QTRY_VERIFY(view->viewport()->findChild<QLineEdit *>());
        QPointer<QLineEdit> editor = view->viewport()->findChild<QLineEdit *>();
        QVERIFY(editor);

        QTest::keyClicks(editor, QStringLiteral("5"), {}, keyDelayMs);
        // The sine moves on and is polled while the person looks for the next key.
        QVERIFY(waitForPolls(batches, 2));
        QTest::keyClicks(editor, QStringLiteral("5"), {}, keyDelayMs);
        QVERIFY(waitForPolls(batches, 2));
        QCOMPARE(editor->text(), QStringLiteral("55"));
        const qsizetype writesBefore = plc.count(QStringLiteral("write R1"));
        // No delay inside this click: the editor closes on the press, before its release.
        QTest::keyClick(editor, Qt::Key_Return);

        // 55 = 0x0037 in the simulator's log.
        QTRY_COMPARE_WITH_TIMEOUT(plc.count(QStringLiteral("write R1 = 0x0037 ")), qsizetype(1),
                                  longWait);
        QCOMPARE(plc.count(QStringLiteral("write R1")), writesBefore + 1);
        QCOMPARE(m_questions.size(), 1);
        QVERIFY2(m_questions.constFirst().contains(QStringLiteral("R1 (station 1) = 55")),
                 qPrintable(m_questions.constFirst()));
        QTRY_VERIFY_WITH_TIMEOUT(table->message().startsWith(QStringLiteral("Wrote R1")), longWait);
    }

    // Issue 48: the PLC acts on a typed value but its answer is lost. The table says the outcome
    // is unknown (not "failed"), reads the value back once the PLC answers, and says it was done.
    void lostAnswerIsUnknownThenReadBack()
    {
        DemoPlc plc;
        QVERIFY(plc.port != 0);
        WatchTableWidget *table = openTable(plc.port, QStringLiteral("R50"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(0), longWait);
        QTableView *view = table->view();
        doubleClick(view, table->viewIndex(model->index(0, WatchTableModel::ValueColumn)));
        QTRY_VERIFY(view->viewport()->findChild<QLineEdit *>());
        QPointer<QLineEdit> editor = view->viewport()->findChild<QLineEdit *>();
        QVERIFY(editor);
        QTest::keyClicks(editor, QStringLiteral("3333"), {}, keyDelayMs);
        FaultConfig mute;
        mute.dropRate = 1.0; // the PLC carries out every request and answers none
        plc.server.setFaults(mute);
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE_WITH_TIMEOUT(plc.count(QStringLiteral("write R50 = 0x0D05 ")), qsizetype(1),
                                  longWait);
        QTRY_VERIFY2_WITH_TIMEOUT(table->message().contains(QStringLiteral("Outcome unknown")),
                                  qPrintable(table->message()), longWait);
        QVERIFY2(!table->message().contains(QStringLiteral("failed")),
                 qPrintable(table->message()));
        if (!qEnvironmentVariableIsEmpty("FATEK_SCREENSHOTS"))
            m_window->grab().save(qEnvironmentVariable("FATEK_SCREENSHOTS")
                                  + QStringLiteral("/write-unknown.png"));
        plc.server.setFaults({});
        QTRY_VERIFY2_WITH_TIMEOUT(table->message().startsWith(QStringLiteral("Wrote R50")),
                                  qPrintable(table->message()), longWait);
        QVERIFY2(table->message().contains(QStringLiteral("Done: confirmed by reading it back")),
                 qPrintable(table->message()));
        QCOMPARE(plc.count(QStringLiteral("write R50")), qsizetype(1)); // sent once
        QCOMPARE(plc.plc.value(addr("R50")), std::optional<std::uint32_t>(3333));
    }

    // Issue 16.2: the format combo, opened and picked with the mouse, applies at once and stays.
    void formatChosenWithTheMouseStays()
    {
        DemoPlc plc;
        QVERIFY(plc.port != 0);
        WatchTableWidget *table = openTable(plc.port, QStringLiteral("R1"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(0), longWait);
        QCOMPARE(model->item(0).format, DisplayFormat::Signed);
        QSignalSpy batches(table->connection(), &Connection::itemValues);

        QTableView *view = table->view();
        const QModelIndex format = table->viewIndex(model->index(0, WatchTableModel::FormatColumn));
        doubleClick(view, format);
        QPointer<QComboBox> combo = view->viewport()->findChild<QComboBox *>();
        QVERIFY(combo);
        QTRY_VERIFY(combo->isVisible());
        QTest::mouseClick(combo, Qt::LeftButton, {}, combo->rect().center(), mouseDelayMs);
        QAbstractItemView *list = combo->view();
        QTRY_VERIFY(list->isVisible());
        const int hex = combo->findText(UiText::format(DisplayFormat::Hex));
        QVERIFY(hex >= 0);
        // Polls keep coming while the person finds the entry.
        QVERIFY(waitForPolls(batches, 2));
        const QRect item = list->visualRect(list->model()->index(hex, 0));
        QTest::mouseMove(list->viewport(), item.center(), mouseDelayMs);
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, item.center(), mouseDelayMs);

        QTRY_COMPARE_WITH_TIMEOUT(model->item(0).format, DisplayFormat::Hex, 5000);
        QTRY_VERIFY(!combo || !combo->isVisible()); // applied and closed, nothing else to do
        QVERIFY(waitForPolls(batches, 3));
        QCOMPARE(model->item(0).format, DisplayFormat::Hex);
        QVERIFY2(model->valueText(0).endsWith(QLatin1Char('h'))
                     || model->valueText(0).startsWith(QStringLiteral("0x")),
                 qPrintable(model->valueText(0)));
    }

    // Issue 16.3: a point forced in the PLC is marked in the watch table, at a modest rate.
    void forcedPointsAreMarked()
    {
        DemoPlc plc;
        QVERIFY(plc.port != 0);
        plc.plc.setDisabled(addr("M1500"), true);
        WatchTableWidget *table = openTable(plc.port, QStringLiteral("Y0 M1500 R1"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        const int y0 = rowOf(model, "Y0");
        const int m1500 = rowOf(model, "M1500");
        const int r1 = rowOf(model, "R1");
        QElapsedTimer clock;
        clock.start();
        QTRY_COMPARE_WITH_TIMEOUT(model->isForced(m1500), std::optional<bool>(true), longWait);
        QCOMPARE(model->isForced(y0), std::optional<bool>(false));
        QCOMPARE(model->isForced(r1), std::optional<bool>()); // registers cannot be forced
        const QModelIndex mark = model->index(m1500, WatchTableModel::ValueColumn);
        QVERIFY(mark.data(Qt::DecorationRole).isValid());
        QVERIFY2(mark.data(Qt::ToolTipRole).toString().contains(QStringLiteral("forced")),
                 qPrintable(mark.data(Qt::ToolTipRole).toString()));
        QVERIFY(!model->index(y0, WatchTableModel::ValueColumn).data(Qt::DecorationRole).isValid());

        // At most one burst (Y and M: two 43 requests) per second.
        const qsizetype before = plc.count(QStringLiteral("read disable flags"));
        clock.restart();
        QTest::qWait(2000);
        const qsizetype reads = plc.count(QStringLiteral("read disable flags")) - before;
        const qint64 seconds = (clock.elapsed() + 999) / 1000;
        qInfo("%lld flag reads in %lld ms", static_cast<long long>(reads),
              static_cast<long long>(clock.elapsed()));
        QVERIFY2(reads <= 2 * (seconds + 1), qPrintable(QString::number(reads)));
        QVERIFY(reads >= 2);

        // Enabled again (by another tool or the CLI): the mark goes.
        plc.plc.setDisabled(addr("M1500"), false);
        QTRY_COMPARE_WITH_TIMEOUT(model->isForced(m1500), std::optional<bool>(false), longWait);
        QVERIFY(!mark.data(Qt::DecorationRole).isValid());
    }

    // Issue 31.1: a PLC polled every 50 ms whose answers now and then come 300 ms late (a stalled
    // line): meanwhile the row keeps its last value and says "late", then "good" again with the
    // next answer. (A line always slower than the interval adapts the period instead, issue 55.)
    void lateValuesShowAsLate()
    {
        DemoPlc plc;
        QVERIFY(plc.port != 0);
        FaultConfig faults;
        faults.spikeRate = 0.3;
        faults.spikeMs = 300;
        plc.server.setFaults(faults);
        WatchTableWidget *table = openTable(plc.port, QStringLiteral("R0"));
        QVERIFY(table);
        table->setIntervalMs(50);
        WatchTableModel *model = table->model();
        const QModelIndex quality = model->index(0, WatchTableModel::QualityColumn);
        QStringList seen; // every quality text the row showed, with its value
        connect(model, &QAbstractItemModel::dataChanged, table, [&] {
            // The quality without the value's age ("late, 0.3 s").
            const QString text = quality.data().toString().section(QStringLiteral(", "), 0, 0);
            if (seen.isEmpty() || !seen.last().startsWith(text + QLatin1Char(' ')))
                seen << text + QLatin1Char(' ')
                            + model->index(0, WatchTableModel::ValueColumn).data().toString();
        });
        QTRY_VERIFY_WITH_TIMEOUT(
            seen.size() >= 4 && seen.filter(QStringLiteral("late ")).size() >= 2, longWait);
        qInfo("the row showed: %s", qPrintable(seen.join(QStringLiteral(" | "))));
        for (const QString &shown : seen.filter(QStringLiteral("late "))) {
            QVERIFY2(!shown.endsWith(QStringLiteral("…")), qPrintable(shown)); // a value, kept
        }
        QTRY_COMPARE_WITH_TIMEOUT(quality.data().toString().section(QStringLiteral(", "), 0, 0),
                                  QStringLiteral("good"), longWait);
        QVERIFY(quality.data(Qt::DecorationRole).isValid());
    }

    // Issue 31.2: connected to station 7 (nobody answers) under auto-detect, a table polling it:
    // Tools > Scan Stations still gets the line between the polls and finds station 1.
    void scanRunsBehindSilentStation()
    {
        DemoPlc plc;
        QVERIFY(plc.port != 0);
        WatchTableWidget *table = openTable(plc.port, QStringLiteral("R0 M0 D0"), 7,
                                            LinkSettings::ProtocolChoice::Auto);
        QVERIFY(table);
        QTest::qWait(1500); // the polls and status reads of station 7 are under way
        auto *action = m_window->findChild<QAction *>(QStringLiteral("scanStationsAction"));
        QVERIFY(action);
        QElapsedTimer clock;
        clock.start();
        action->trigger();
        QDialog *dialog = m_window->findChild<QDialog *>(QStringLiteral("stationScanDialog"));
        QVERIFY(dialog);
        auto *progress = dialog->findChild<QProgressBar *>(QStringLiteral("scanProgress"));
        auto *stations = dialog->findChild<QListWidget *>(QStringLiteral("stationList"));
        QVERIFY(progress && stations);
        QTRY_VERIFY_WITH_TIMEOUT(
            progress->maximum() > 0 && progress->value() == progress->maximum(), 30000);
        qInfo("scan of %d stations behind a silent station: %lld ms", progress->maximum(),
              static_cast<long long>(clock.elapsed()));
        QCOMPARE(stations->count(), 1);
        QVERIFY2(stations->item(0)->text().startsWith(QStringLiteral("Station 1 ")),
                 qPrintable(stations->item(0)->text()));
        dialog->close();
    }

    // Issue 31.1: R0 moved to station 7 (nobody answers), R1 stays on station 1 at 500 ms. Once
    // station 7 rests, the Connections dock and the status bar show the requests station 1 still
    // gets, every second, not 0.0.
    void rateCountsBesideSilentStation()
    {
        DemoPlc plc;
        QVERIFY(plc.port != 0);
        WatchTableWidget *table = openTable(plc.port, QStringLiteral("R0 R1"));
        QVERIFY(table);
        table->setIntervalMs(500);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(rowOf(model, "R1")), longWait);
        // From the first seconds on, not only once a window of samples has filled.
        auto *dock = m_window->findChild<ConnectionsPanel *>();
        QVERIFY(dock);
        const QModelIndex firstRate
            = dock->view()->model()->index(0, ConnectionListModel::RateColumn);
        QTRY_VERIFY2_WITH_TIMEOUT(firstRate.data().toString().toDouble() > 0,
                                  qPrintable(firstRate.data().toString()), 1500);
        QTableView *view = table->view();
        doubleClick(view, table->viewIndex(
                              model->index(rowOf(model, "R0"), WatchTableModel::StationColumn)));
        QTRY_VERIFY(view->viewport()->findChild<QLineEdit *>());
        QLineEdit *editor = view->viewport()->findChild<QLineEdit *>();
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("7"), {}, keyDelayMs);
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE(model->item(rowOf(model, "R0")).station, quint8(7));

        auto *panel = m_window->findChild<ConnectionsPanel *>();
        QVERIFY(panel);
        const QModelIndex state
            = panel->view()->model()->index(0, ConnectionListModel::StateColumn);
        QTRY_VERIFY2_WITH_TIMEOUT(state.data().toString().contains(QStringLiteral("rests until")),
                                  qPrintable(state.data().toString()), longWait);
        const QModelIndex rate = panel->view()->model()->index(0, ConnectionListModel::RateColumn);
        auto *linkStatus = m_window->findChild<QLabel *>(QStringLiteral("linkStatus"));
        QVERIFY(linkStatus);
        QStringList shown;
        for (int i = 0; i < 8; ++i) {
            QTest::qWait(400);
            shown << rate.data().toString();
            // R1 twice a second, and the connection's status reads: at least 1.5 per second.
            QVERIFY2(rate.data().toString().toDouble() >= 1.5, qPrintable(shown.join(u' ')));
            QVERIFY2(linkStatus->text().contains(rate.data().toString() + QStringLiteral(" req/s")),
                     qPrintable(linkStatus->text()));
        }
        qInfo("Req/s while station 7 rests: %s", qPrintable(shown.join(u' ')));
    }

    // Issue 16.4: station 5 asked, the PLC is station 1: the link and the rows say so in time.
    void wrongStationSaysNoAnswer()
    {
        DemoPlc plc;
        QVERIFY(plc.port != 0);
        WatchTableWidget *table = openTable(plc.port, QStringLiteral("R0"), 5);
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QElapsedTimer clock;
        clock.start();
        auto *panel = m_window->findChild<ConnectionsPanel *>();
        QVERIFY(panel);
        const QModelIndex state
            = panel->view()->model()->index(0, ConnectionListModel::StateColumn);
        const QString expected = QStringLiteral("no answer from station 5");
        const SavedConnection saved = savedFor(plc.port, 5);
        // One request's timeout and retries, plus a statistics report (4 Hz) and slack for a busy
        // machine.
        const int budget = saved.settings.timeoutMs * (saved.settings.retries + 1) + 250 + 1500;
        QTRY_VERIFY_WITH_TIMEOUT(state.data().toString().contains(expected), budget);
        qInfo("link says \"%s\" after %lld ms", qPrintable(state.data().toString()),
              static_cast<long long>(clock.elapsed()));
        // The row: "no answer" (its station is in the next column), the whole story in the tooltip.
        const QModelIndex quality = model->index(0, WatchTableModel::QualityColumn);
        QTRY_COMPARE_WITH_TIMEOUT(quality.data().toString(), QStringLiteral("no answer"), budget);
        QVERIFY(quality.data(Qt::DecorationRole).isValid());
        QVERIFY2(quality.data(Qt::ToolTipRole)
                     .toString()
                     .contains(QStringLiteral("No answer from "
                                              "station 5")),
                 qPrintable(quality.data(Qt::ToolTipRole).toString()));
        auto *linkStatus = m_window->findChild<QLabel *>(QStringLiteral("linkStatus"));
        QVERIFY(linkStatus);
        QTRY_VERIFY2_WITH_TIMEOUT(linkStatus->text().contains(expected),
                                  qPrintable(linkStatus->text()), budget);
        QVERIFY(!model->hasValue(0));

        // Issue 31: after 3 requests without an answer the station is demoted; the link and the
        // row say until when it rests. Budget: the 3 poll requests and the connection's own status
        // reads between them, each with its retries, plus the statistics report and slack.
        const int demotedBudget
            = saved.settings.timeoutMs * (saved.settings.retries + 1) * 6 + 1750;
        QTRY_VERIFY2_WITH_TIMEOUT(
            state.data().toString().contains(QStringLiteral("station 5 rests until ")),
            qPrintable(state.data().toString()), demotedBudget);
        QTRY_VERIFY2_WITH_TIMEOUT(
            quality.data(Qt::ToolTipRole).toString().contains(QStringLiteral("polled again at ")),
            qPrintable(quality.data(Qt::ToolTipRole).toString()), demotedBudget);
        QCOMPARE(quality.data().toString(), QStringLiteral("no answer"));

        // The PLC is set to station 5: answers come (at the next try of the demoted station) and
        // the warnings go.
        plc.server.setStation(5);
        QTRY_COMPARE_WITH_TIMEOUT(model->quality(0), ValueQuality::Good, longWait);
        QTRY_VERIFY_WITH_TIMEOUT(!state.data().toString().contains(expected), longWait);
        QTRY_VERIFY_WITH_TIMEOUT(!linkStatus->text().contains(expected), longWait);
        QCOMPARE(quality.data().toString().section(QStringLiteral(", "), 0, 0),
                 QStringLiteral("good"));
    }
};

QTEST_MAIN(TestUiLiveTable)
#include "tst_ui_livetable.moc"
