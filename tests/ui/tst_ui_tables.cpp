// Watch tables that handle like the tools engineers know (issue 34), at a laptop's 1366x768 with
// the real main window and a simulated FBs running the demo ladder (R1 a sine, Y0 blinking, R0
// counting scans) over loopback TCP, so that values change under the person's hands: sorting by
// a header click and back to the own order, the filter line, undo and redo of edits, moves by
// keyboard and drag, copy and paste of rows, one format for several rows, the unsaved mark and
// its question, the values' age beside their quality, the trend of a register shown in hex, and
// the last column fitting the window. What reached the PLC is counted on the simulator's side.
#include "core/sim/faultconfig.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"
#include "ui/connection/connection.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/trend/trendview.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtableproxy.h"
#include "ui/watch/watchtableview.h"
#include "uitestutil.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QHeaderView>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QtCharts/QChart>
#include <QtCharts/QValueAxis>

#include <memory>
#include <set>

using namespace Fatek;

namespace {

constexpr int longWait = 20000;
// A person types about 5 characters a second and needs a moment to aim the mouse.
constexpr int keyDelayMs = 120;
constexpr int mouseDelayMs = 300;
const QSize laptop(1366, 768);

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
    qsizetype writes() const
    {
        qsizetype n = 0;
        for (const QString &line : log)
            n += line.contains(QLatin1String("write")) ? 1 : 0;
        return n;
    }
};

// The addresses of a table's rows as its view shows them, top to bottom.
QStringList shownAddresses(const WatchTableWidget *table)
{
    QStringList out;
    const QAbstractItemModel *m = table->view()->model();
    for (int r = 0; r < m->rowCount(); ++r)
        out << m->index(r, WatchTableModel::AddressColumn).data().toString();
    return out;
}

// The chart's labels that QtCharts cut to "…" (or "..."), joined; empty when every label is whole.
QString cutChartLabels(TrendView *trend)
{
    QStringList cut;
    for (QGraphicsItem *item : trend->chart()->scene()->items()) {
        if (auto *text = dynamic_cast<QGraphicsTextItem *>(item);
            text && text->isVisible()
            && (text->toPlainText().contains(QChar(0x2026))
                || text->toPlainText().contains(QLatin1String("..."))))
            cut << text->toPlainText();
    }
    return cut.join(QStringLiteral(" | "));
}

// The value axes' labels (numbers) that reach into the plot or into each other's place, joined;
// empty when every label has its own room beside the plot.
QString overlappingAxisLabels(TrendView *trend)
{
    const QRectF plot = trend->chart()->plotArea().adjusted(1, 1, -1, -1);
    std::vector<std::pair<QString, QRectF>> labels;
    for (QGraphicsItem *item : trend->chart()->scene()->items()) {
        auto *text = dynamic_cast<QGraphicsTextItem *>(item);
        if (!text || !text->isVisible())
            continue;
        bool number = false;
        text->toPlainText().toDouble(&number);
        if (number)
            labels.emplace_back(text->toPlainText(), text->sceneBoundingRect());
    }
    QStringList bad;
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const auto &[label, rect] = labels[i];
        // Labels sit beside the plot: left or right of it, never across its edge.
        if (rect.right() > plot.left() && rect.left() < plot.right())
            bad << label + QStringLiteral(" in the plot");
        for (std::size_t j = i + 1; j < labels.size(); ++j) {
            // Shrunk by the text's own margins: touching boxes are not overlapping text.
            if (rect.adjusted(1, 1, -1, -1).intersects(labels[j].second.adjusted(1, 1, -1, -1)))
                bad << label + QStringLiteral(" over ") + labels[j].first;
        }
    }
    return bad.join(QStringLiteral(" | "));
}

// The addresses in the model's own order.
QStringList ownAddresses(const WatchTableModel *model)
{
    QStringList out;
    for (int r = 0; r < model->rowCount(); ++r)
        out << QString::fromStdString(model->item(r).address.toString());
    return out;
}

int rowOf(const WatchTableModel *model, const QString &address)
{
    return static_cast<int>(ownAddresses(model).indexOf(address));
}

// The view's index of a model row's cell.
QModelIndex cellOf(const WatchTableWidget *table, const QString &address, int column)
{
    return table->viewIndex(table->model()->index(rowOf(table->model(), address), column));
}

// A widget a person can click: shown, with some size, inside the screen.
bool onScreen(const QWidget *w)
{
    if (!w || !w->isVisible() || w->width() < 10 || w->height() < 10)
        return false;
    const QRect global(w->mapToGlobal(QPoint(0, 0)), w->size());
    return w->screen()->availableGeometry().contains(global);
}

void clickCell(QTableView *view, const QModelIndex &index, Qt::KeyboardModifiers modifiers = {})
{
    QTest::mouseClick(view->viewport(), Qt::LeftButton, modifiers, view->visualRect(index).center(),
                      mouseDelayMs);
}

void clickHeader(QTableView *view, int column)
{
    QHeaderView *header = view->horizontalHeader();
    const QPoint at(header->sectionViewportPosition(column) + header->sectionSize(column) / 2,
                    header->height() / 2);
    QTest::mouseClick(header->viewport(), Qt::LeftButton, {}, at, mouseDelayMs);
}

// Types into the cell's editor (F2 on the current cell, as a person edits in place) and Enter.
bool typeIntoCell(QTableView *view, const QModelIndex &index, const QString &text)
{
    clickCell(view, index);
    QTest::keyClick(view->viewport(), Qt::Key_F2, {}, keyDelayMs);
    auto *editor = view->viewport()->findChild<QLineEdit *>();
    if (!editor || !editor->isVisible())
        return false;
    editor->selectAll();
    QTest::keyClicks(editor, text, {}, keyDelayMs);
    QTest::keyClick(editor, Qt::Key_Return);
    return true;
}

// A keyboard shortcut pressed while the table has the focus.
void press(QTableView *view, int key, Qt::KeyboardModifiers modifiers = Qt::ControlModifier)
{
    QTest::keyClick(view->viewport(), static_cast<Qt::Key>(key), modifiers, keyDelayMs);
}

// "good, 0.4 s" -> 0.4; -1 when the text has no age.
double ageSeconds(const QString &quality)
{
    static const QRegularExpression age(QStringLiteral(R"(, (\d+(?:[.,]\d)?) s$)"));
    const QRegularExpressionMatch m = age.match(quality);
    if (!m.hasMatch())
        return -1;
    QString number = m.captured(1);
    number.replace(QLatin1Char(','), QLatin1Char('.'));
    return number.toDouble();
}

} // namespace

class TestUiTables : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;
    std::unique_ptr<MainWindow> m_window;
    std::unique_ptr<DemoPlc> m_plc;

    // The window on the laptop's screen, connected to the demo PLC, with `items` typed into its
    // first table at a person's pace.
    WatchTableWidget *openTable(const QString &items, int intervalMs = 200, int timeoutMs = 1000)
    {
        m_plc = std::make_unique<DemoPlc>();
        if (m_plc->port == 0)
            return nullptr;
        m_window = std::make_unique<MainWindow>();
        m_window->setConfirmHandler([](QWidget *, const QString &) { return true; });
        m_window->show();
        if (!QTest::qWaitForWindowExposed(m_window.get()))
            return nullptr;
        m_window->activateWindow();
        if (!QTest::qWaitForWindowActive(m_window.get()))
            return nullptr;
        SavedConnection saved;
        saved.name = QStringLiteral("Bench PLC");
        saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_plc->port);
        saved.settings.timeoutMs = timeoutMs;
        saved.settings.retries = 1;
        saved.station = 1;
        Connection *c = m_window->openConnection(saved, false);
        if (!QTest::qWaitFor([c] { return c->linkState() == LinkState::Connected; }, longWait))
            return nullptr;
        WatchTableWidget *table = m_window->currentWatchTable();
        table->setIntervalMs(intervalMs);
        QLineEdit *edit = table->addressEdit();
        if (!onScreen(edit))
            return nullptr;
        QTest::mouseClick(edit, Qt::LeftButton, {}, QPoint(), mouseDelayMs);
        QTest::keyClicks(edit, items, {}, 20);
        QTest::keyClick(edit, Qt::Key_Return);
        return table;
    }

    // Selects the rows of `addresses` by clicks (Ctrl for the others), adds them to the trend
    // from the table's menu and opens the trend; null when any step fails.
    TrendView *addToTrend(WatchTableWidget *table, const QStringList &addresses)
    {
        QTableView *view = table->view();
        for (qsizetype i = 0; i < addresses.size(); ++i)
            clickCell(view, cellOf(table, addresses.at(i), WatchTableModel::AddressColumn),
                      i == 0 ? Qt::NoModifier : Qt::ControlModifier);
        QAction *add = nullptr;
        for (QAction *a : view->actions()) {
            if (a->text() == QLatin1String("Add to &Trend"))
                add = a;
        }
        if (!add)
            return nullptr;
        add->trigger();
        TrendView *trend = m_window->trendView();
        if (trend->itemCount() != addresses.size() || !m_window->openTool(QStringLiteral("trend"))
            || !QTest::qWaitFor([trend] { return trend->isVisible(); }))
            return nullptr;
        return trend;
    }

    static bool allValues(const WatchTableModel *model)
    {
        for (int r = 0; r < model->rowCount(); ++r) {
            if (!model->hasValue(r))
                return false;
        }
        return model->rowCount() > 0;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_tables"));
        QCOMPARE(QGuiApplication::primaryScreen()->size(), laptop);
    }

    void cleanup()
    {
        m_window.reset(); // deleted, not closed: no question on the way out
        m_plc.reset();
    }

    // A header click sorts, a second the other way, a third shows the own order again; so does
    // Own Order. The model keeps its rows in the own order all along.
    void sortByHeaderAndBackToOwnOrder()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R5 R1 R12 R0"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(allValues(model), longWait);
        const QStringList own{QStringLiteral("R5"), QStringLiteral("R1"), QStringLiteral("R12"),
                              QStringLiteral("R0")};
        QCOMPARE(shownAddresses(table), own);
        QTableView *view = table->view();
        QVERIFY(onScreen(view->horizontalHeader()));

        clickHeader(view, WatchTableModel::AddressColumn);
        // By number, not by text: R12 after R5.
        const QStringList ascending{QStringLiteral("R0"), QStringLiteral("R1"),
                                    QStringLiteral("R5"), QStringLiteral("R12")};
        QTRY_COMPARE(shownAddresses(table), ascending);
        QCOMPARE(ownAddresses(model), own);
        clickHeader(view, WatchTableModel::AddressColumn);
        QStringList descending = ascending;
        std::reverse(descending.begin(), descending.end());
        QTRY_COMPARE(shownAddresses(table), descending);
        clickHeader(view, WatchTableModel::AddressColumn);
        QTRY_COMPARE(shownAddresses(table), own);

        // Sorted by value while the R0 scan counter and the sine change: by number, not by text
        // (9 before 10).
        QVERIFY(m_plc->plc.setValue(*Address::parse("R5"), 9));
        QVERIFY(m_plc->plc.setValue(*Address::parse("R12"), 10));
        QTRY_VERIFY_WITH_TIMEOUT(model->valueText(rowOf(model, QStringLiteral("R12")))
                                     == QStringLiteral("10"),
                                 longWait);
        clickHeader(view, WatchTableModel::ValueColumn);
        QTRY_COMPARE(view->horizontalHeader()->sortIndicatorSection(),
                     int(WatchTableModel::ValueColumn));
        QTRY_VERIFY(shownAddresses(table).indexOf(QStringLiteral("R5"))
                    < shownAddresses(table).indexOf(QStringLiteral("R12")));
        QCOMPARE(ownAddresses(model), own);

        // The menu's Own Order.
        QAction *ownOrder = view->findChild<QAction *>(QStringLiteral("ownOrderAction"));
        QVERIFY(ownOrder && view->actions().contains(ownOrder));
        ownOrder->trigger();
        QTRY_COMPARE(shownAddresses(table), own);
        QCOMPARE(view->horizontalHeader()->sortIndicatorSection(), -1);
    }

    // The filter line above the table keeps the rows whose address, name or comment has the
    // text; moving rows waits until it is cleared.
    void filterByAddressNameOrComment()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R0 R1 R2 R3"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(allValues(model), longWait);
        QTableView *view = table->view();
        QVERIFY(typeIntoCell(view, cellOf(table, QStringLiteral("R2"), WatchTableModel::NameColumn),
                             QStringLiteral("Tank level")));
        QTRY_COMPARE(model->item(2).name, QStringLiteral("Tank level"));
        QVERIFY(typeIntoCell(view,
                             cellOf(table, QStringLiteral("R3"), WatchTableModel::CommentColumn),
                             QStringLiteral("tank outlet valve")));
        QTRY_COMPARE(model->item(3).comment, QStringLiteral("tank outlet valve"));

        auto *filter = table->findChild<QLineEdit *>(QStringLiteral("filterEdit"));
        QVERIFY(onScreen(filter));
        // Above the rows.
        QVERIFY(filter->mapTo(m_window.get(), QPoint(0, filter->height())).y()
                <= view->mapTo(m_window.get(), QPoint(0, 0)).y());
        QTest::mouseClick(filter, Qt::LeftButton, {}, QPoint(), mouseDelayMs);
        QTest::keyClicks(filter, QStringLiteral("tank"), {}, keyDelayMs);
        QTRY_COMPARE(shownAddresses(table),
                     (QStringList{QStringLiteral("R2"), QStringLiteral("R3")}));
        QCOMPARE(model->rowCount(), 4);

        // Ctrl+Down while filtered moves nothing (a shortcut acts at once, or never).
        auto *moveDown = view->findChild<QAction *>(QStringLiteral("moveDownAction"));
        QVERIFY(moveDown && !moveDown->isEnabled());
        clickCell(view, view->model()->index(0, WatchTableModel::AddressColumn));
        press(view, Qt::Key_Down);
        QCOMPARE(ownAddresses(model), (QStringList{QStringLiteral("R0"), QStringLiteral("R1"),
                                                   QStringLiteral("R2"), QStringLiteral("R3")}));

        // An address.
        QTest::mouseClick(filter, Qt::LeftButton, {}, QPoint(), mouseDelayMs);
        filter->selectAll();
        QTest::keyClicks(filter, QStringLiteral("r1"), {}, keyDelayMs);
        QTRY_COMPARE(shownAddresses(table), QStringList{QStringLiteral("R1")});
        // Cleared: all rows, in their order.
        filter->selectAll();
        QTest::keyClick(filter, Qt::Key_Backspace, {}, keyDelayMs);
        QTRY_COMPARE(shownAddresses(table), ownAddresses(model));
        QCOMPARE(shownAddresses(table).size(), 4);
    }

    // Ctrl+Z takes back a typed name, an address, a removed row, an added one and a format;
    // Ctrl+Y and Ctrl+Shift+Z do them again. A value written to the PLC is not taken back.
    void undoRedoEdits()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R0 R1 R2"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(allValues(model), longWait);
        QTableView *view = table->view();

        // A name.
        QVERIFY(typeIntoCell(view, cellOf(table, QStringLiteral("R1"), WatchTableModel::NameColumn),
                             QStringLiteral("Sine")));
        QTRY_COMPARE(model->item(1).name, QStringLiteral("Sine"));
        press(view, Qt::Key_Z);
        QTRY_COMPARE(model->item(1).name, QString());
        press(view, Qt::Key_Y);
        QTRY_COMPARE(model->item(1).name, QStringLiteral("Sine"));
        press(view, Qt::Key_Z);
        QTRY_COMPARE(model->item(1).name, QString());
        press(view, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_COMPARE(model->item(1).name, QStringLiteral("Sine"));

        // An address typed over: the row watches the new element, and back.
        QVERIFY(typeIntoCell(view,
                             cellOf(table, QStringLiteral("R2"), WatchTableModel::AddressColumn),
                             QStringLiteral("R7")));
        QTRY_COMPARE(ownAddresses(model).value(2), QStringLiteral("R7"));
        press(view, Qt::Key_Z);
        QTRY_COMPARE(ownAddresses(model).value(2), QStringLiteral("R2"));
        QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(2), longWait);

        // A row removed with Delete comes back in its place, name and all.
        clickCell(view, cellOf(table, QStringLiteral("R1"), WatchTableModel::AddressColumn));
        QTest::keyClick(view->viewport(), Qt::Key_Delete, {}, keyDelayMs);
        QTRY_COMPARE(ownAddresses(model),
                     (QStringList{QStringLiteral("R0"), QStringLiteral("R2")}));
        press(view, Qt::Key_Z);
        QTRY_COMPARE(ownAddresses(model), (QStringList{QStringLiteral("R0"), QStringLiteral("R1"),
                                                       QStringLiteral("R2")}));
        QCOMPARE(model->item(1).name, QStringLiteral("Sine"));
        QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(1), longWait);

        // Rows added with the entry line go with one Ctrl+Z.
        QTest::mouseClick(table->addressEdit(), Qt::LeftButton, {}, QPoint(), mouseDelayMs);
        QTest::keyClicks(table->addressEdit(), QStringLiteral("X0..X3"), {}, keyDelayMs);
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        QTRY_COMPARE(model->rowCount(), 7);
        clickCell(view, view->model()->index(0, WatchTableModel::AddressColumn));
        press(view, Qt::Key_Z);
        QTRY_COMPARE(model->rowCount(), 3);
        press(view, Qt::Key_Y);
        QTRY_COMPARE(model->rowCount(), 7);
        press(view, Qt::Key_Z);
        QTRY_COMPARE(model->rowCount(), 3);

        // One more step, the last before a write.
        QVERIFY(typeIntoCell(view, cellOf(table, QStringLiteral("R1"), WatchTableModel::NameColumn),
                             QStringLiteral("Sine wave")));
        QTRY_COMPARE(model->item(1).name, QStringLiteral("Sine wave"));
        model->undoStack()->setClean();
        const int steps = model->undoStack()->count();

        // A value written to the PLC: the write is not a step, Ctrl+Z does not undo it.
        const qsizetype writes = m_plc->writes();
        QVERIFY(typeIntoCell(view,
                             cellOf(table, QStringLiteral("R2"), WatchTableModel::ValueColumn),
                             QStringLiteral("1234")));
        QTRY_COMPARE_WITH_TIMEOUT(m_plc->plc.value(*Address::parse("R2")).value_or(0), 1234u,
                                  longWait);
        QTRY_COMPARE_WITH_TIMEOUT(model->valueText(2), QStringLiteral("1234"), longWait);
        QCOMPARE(m_plc->writes(), writes + 1);
        QCOMPARE(model->undoStack()->count(), steps);
        press(view, Qt::Key_Z);
        QTRY_COMPARE(model->item(1).name, QStringLiteral("Sine"));
        // Polls go on: the PLC still holds what was written.
        QSignalSpy batches(table->connection(), &Connection::itemValues);
        QTRY_VERIFY_WITH_TIMEOUT(batches.count() >= 3, longWait);
        QCOMPARE(model->valueText(2), QStringLiteral("1234"));
        QCOMPARE(m_plc->writes(), writes + 1);
    }

    // Ctrl+Up / Ctrl+Down move the selected rows; a drag of rows drops them between others.
    void reorderByKeyboardAndDrag()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R0 R1 R2 R3 R4"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(allValues(model), longWait);
        QTableView *view = table->view();

        clickCell(view, cellOf(table, QStringLiteral("R1"), WatchTableModel::NameColumn));
        press(view, Qt::Key_Down);
        QTRY_COMPARE(ownAddresses(model), (QStringList{"R0", "R2", "R1", "R3", "R4"}));
        press(view, Qt::Key_Down);
        QTRY_COMPARE(ownAddresses(model), (QStringList{"R0", "R2", "R3", "R1", "R4"}));
        // The selection goes along: R1 and R4 (Ctrl+click) go up together.
        clickCell(view, cellOf(table, QStringLiteral("R4"), WatchTableModel::NameColumn),
                  Qt::ControlModifier);
        press(view, Qt::Key_Up);
        QTRY_COMPARE(ownAddresses(model), (QStringList{"R0", "R2", "R1", "R4", "R3"}));
        press(view, Qt::Key_Z);
        QTRY_COMPARE(ownAddresses(model), (QStringList{"R0", "R2", "R3", "R1", "R4"}));
        // Values still reach their rows.
        QTRY_VERIFY_WITH_TIMEOUT(model->valueText(rowOf(model, QStringLiteral("R0"))).toInt() > 0,
                                 longWait);

        // Drag R4 (selected by a click) to the top. The offscreen platform has no drag loop: the
        // drag's events are given to the view as the window system would.
        clickCell(view, cellOf(table, QStringLiteral("R4"), WatchTableModel::NameColumn));
        QVERIFY(view->dragEnabled());
        auto *watchView = qobject_cast<WatchTableView *>(view);
        QVERIFY(watchView);
        std::unique_ptr<QMimeData> data(watchView->rowsMimeData());
        QVERIFY(data);
        const QPoint top = view->visualRect(view->model()->index(0, 0)).topLeft() + QPoint(20, 2);
        QDragEnterEvent enter(top, Qt::MoveAction, data.get(), Qt::LeftButton, {});
        QApplication::sendEvent(view->viewport(), &enter);
        QVERIFY(enter.isAccepted());
        QDragMoveEvent move(top, Qt::MoveAction, data.get(), Qt::LeftButton, {});
        QApplication::sendEvent(view->viewport(), &move);
        QVERIFY(move.isAccepted());
        QDropEvent drop(top, Qt::MoveAction, data.get(), Qt::LeftButton, {});
        QApplication::sendEvent(view->viewport(), &drop);
        QVERIFY(drop.isAccepted());
        QTRY_COMPARE(ownAddresses(model), (QStringList{"R4", "R0", "R2", "R3", "R1"}));
        press(view, Qt::Key_Z);
        QTRY_COMPARE(ownAddresses(model), (QStringList{"R0", "R2", "R3", "R1", "R4"}));

        // Sorted: no moves, no drags.
        clickHeader(view, WatchTableModel::AddressColumn);
        QTRY_VERIFY(!view->dragEnabled());
        clickCell(view, view->model()->index(1, WatchTableModel::NameColumn));
        QVERIFY(!view->findChild<QAction *>(QStringLiteral("moveDownAction"))->isEnabled());
        press(view, Qt::Key_Down);
        QCOMPARE(ownAddresses(model), (QStringList{"R0", "R2", "R3", "R1", "R4"}));
    }

    // Ctrl+C copies the selected rows as tab-separated text (address, name, value, format,
    // quality, comment); Ctrl+V in another table adds them as rows, writing nothing.
    void copyAndPasteRows()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R0 R1 Y0"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(allValues(model), longWait);
        QTableView *view = table->view();
        QVERIFY(typeIntoCell(view, cellOf(table, QStringLiteral("R1"), WatchTableModel::NameColumn),
                             QStringLiteral("Sine")));
        QTRY_COMPARE(model->item(1).name, QStringLiteral("Sine"));
        QVERIFY(typeIntoCell(view,
                             cellOf(table, QStringLiteral("R1"), WatchTableModel::CommentColumn),
                             QStringLiteral("10 s period")));
        QTRY_COMPARE(model->item(1).comment, QStringLiteral("10 s period"));
        QVERIFY(model->setFormat(1, DisplayFormat::Hex, false));
        QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(1), longWait);

        QApplication::clipboard()->clear();
        clickCell(view, cellOf(table, QStringLiteral("R1"), WatchTableModel::AddressColumn));
        clickCell(view, cellOf(table, QStringLiteral("Y0"), WatchTableModel::AddressColumn),
                  Qt::ShiftModifier);
        press(view, Qt::Key_C);
        QTRY_VERIFY(!QApplication::clipboard()->text().isEmpty());
        const QStringList lines
            = QApplication::clipboard()->text().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        QCOMPARE(lines.at(0), QStringLiteral("address\tname\tvalue\tformat\tquality\tcomment"));
        const QStringList sine = lines.at(1).split(QLatin1Char('\t'));
        QCOMPARE(sine.size(), 6);
        QCOMPARE(sine.at(0), QStringLiteral("R1"));
        QCOMPARE(sine.at(1), QStringLiteral("Sine"));
        QVERIFY2(sine.at(2).startsWith(QStringLiteral("0x")), qPrintable(sine.at(2)));
        QCOMPARE(sine.at(3), QStringLiteral("hex"));
        QVERIFY2(sine.at(4).startsWith(QStringLiteral("good")), qPrintable(sine.at(4)));
        QCOMPARE(sine.at(5), QStringLiteral("10 s period"));
        QVERIFY2(lines.at(2).startsWith(QStringLiteral("Y0\t\t")), qPrintable(lines.at(2)));

        // Another table (Ctrl+T), its rows pasted with Ctrl+V.
        const qsizetype writes = m_plc->writes();
        QTest::keyClick(m_window.get(), Qt::Key_T, Qt::ControlModifier, keyDelayMs);
        QTRY_VERIFY(m_window->currentWatchTable() != table);
        WatchTableWidget *other = m_window->currentWatchTable();
        QVERIFY(onScreen(other->view()));
        QTest::mouseClick(other->view()->viewport(), Qt::LeftButton, {}, QPoint(50, 20),
                          mouseDelayMs);
        press(other->view(), Qt::Key_V);
        QTRY_COMPARE(other->model()->rowCount(), 2);
        const WatchItemSpec pasted = other->model()->item(0);
        QCOMPARE(QString::fromStdString(pasted.address.toString()), QStringLiteral("R1"));
        QCOMPARE(pasted.name, QStringLiteral("Sine"));
        QCOMPARE(pasted.format, DisplayFormat::Hex);
        QCOMPARE(pasted.comment, QStringLiteral("10 s period"));
        QCOMPARE(QString::fromStdString(other->model()->item(1).address.toString()),
                 QStringLiteral("Y0"));
        QTRY_VERIFY_WITH_TIMEOUT(allValues(other->model()), longWait);
        QCOMPARE(m_plc->writes(), writes);
        // One step to take back.
        press(other->view(), Qt::Key_Z);
        QTRY_COMPARE(other->model()->rowCount(), 0);
    }

    // Rows selected, F2 on a format cell, a format picked: every selected row takes it, and one
    // Ctrl+Z gives every row its own back.
    void formatForSelectedRows()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R0 R1 R2 Y0"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(allValues(model), longWait);
        QVERIFY(model->setFormat(0, DisplayFormat::Unsigned, false));
        QTableView *view = table->view();

        clickCell(view, cellOf(table, QStringLiteral("R0"), WatchTableModel::FormatColumn));
        clickCell(view, cellOf(table, QStringLiteral("R2"), WatchTableModel::FormatColumn),
                  Qt::ShiftModifier);
        QCOMPARE(table->selectedRows(), (QList<int>{0, 1, 2}));
        QTest::keyClick(view->viewport(), Qt::Key_F2, {}, keyDelayMs);
        QPointer<QComboBox> combo = view->viewport()->findChild<QComboBox *>();
        QVERIFY(combo);
        QTRY_VERIFY(combo->isVisible());
        QTest::mouseClick(combo, Qt::LeftButton, {}, combo->rect().center(), mouseDelayMs);
        QAbstractItemView *list = combo->view();
        QTRY_VERIFY(list->isVisible());
        const int hex = combo->findData(static_cast<int>(DisplayFormat::Hex));
        QVERIFY(hex >= 0);
        const QRect item = list->visualRect(list->model()->index(hex, 0));
        QTest::mouseMove(list->viewport(), item.center(), mouseDelayMs);
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, item.center(), mouseDelayMs);
        for (int r = 0; r < 3; ++r)
            QTRY_COMPARE(model->item(r).format, DisplayFormat::Hex);
        QCOMPARE(model->item(3).format, DisplayFormat::Bit);
        QTRY_VERIFY_WITH_TIMEOUT(model->valueText(1).startsWith(QStringLiteral("0x")), longWait);

        press(view, Qt::Key_Z);
        QTRY_COMPARE(model->item(0).format, DisplayFormat::Unsigned);
        QCOMPARE(model->item(1).format, DisplayFormat::Signed);
        QCOMPARE(model->item(2).format, DisplayFormat::Signed);

        // The context menu's Set Format, on the rows selected with Ctrl+A.
        press(view, Qt::Key_A);
        QMenu *formats = table->findChild<QMenu *>(QStringLiteral("formatMenu"));
        QVERIFY(formats && view->actions().contains(formats->menuAction()));
        formats->popup(view->mapToGlobal(QPoint(40, 40)));
        QTRY_VERIFY(formats->isVisible());
        // Y0 is among them: only what every row can show is offered.
        QAction *binary = formats->findChild<QAction *>(QStringLiteral("format_binary"));
        QVERIFY(binary);
        QVERIFY(!formats->findChild<QAction *>(QStringLiteral("format_signed")));
        QTest::mouseClick(formats, Qt::LeftButton, {}, formats->actionGeometry(binary).center(),
                          mouseDelayMs);
        for (int r = 0; r < 4; ++r)
            QTRY_COMPARE(model->item(r).format, DisplayFormat::Binary);
    }

    // An edit marks the title ([*], windowModified); opening another list asks Save, Discard or
    // Cancel; Save writes the list; quitting asks too.
    void unsavedMarkAndQuestion()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R0 R1"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(allValues(model), longWait);
        QTRY_VERIFY(m_window->isWindowModified());
        QVERIFY(m_window->windowTitle().contains(QStringLiteral("[*]")));
        const QString path = QDir(m_settingsDir.path()).filePath(QStringLiteral("bench.json"));
        QVERIFY(m_window->saveWatchList(path));
        QVERIFY(!m_window->isWindowModified());

        // Values keep coming: not a change.
        QSignalSpy batches(table->connection(), &Connection::itemValues);
        QTRY_VERIFY_WITH_TIMEOUT(batches.count() >= 3, longWait);
        QVERIFY(!m_window->isWindowModified());
        QTableView *view = table->view();
        QVERIFY(typeIntoCell(view, cellOf(table, QStringLiteral("R1"), WatchTableModel::NameColumn),
                             QStringLiteral("Sine")));
        QTRY_VERIFY(m_window->isWindowModified());
        // Undone: as saved again.
        press(view, Qt::Key_Z);
        QTRY_VERIFY(!m_window->isWindowModified());
        press(view, Qt::Key_Y);
        QTRY_VERIFY(m_window->isWindowModified());

        // Ctrl+O: the question; Cancel keeps everything.
        const QString asked = UiTestUtil::answerModal(
            [&] { QTest::keyClick(m_window.get(), Qt::Key_O, Qt::ControlModifier); },
            UiTestUtil::clickButton("cancelButton"));
        QVERIFY2(asked.contains(QStringLiteral("bench.json")), qPrintable(asked));
        QVERIFY(m_window->isWindowModified());
        QCOMPARE(model->item(1).name, QStringLiteral("Sine"));

        // Ctrl+O, Save: the list is written, then the file dialog (closed unanswered).
        bool saved = false;
        bool fileDialog = false;
        QTimer hand;
        hand.setInterval(100);
        connect(&hand, &QTimer::timeout, this, [&] {
            QWidget *modal = QApplication::activeModalWidget();
            if (auto *box = qobject_cast<QMessageBox *>(modal); box && !saved) {
                saved = true;
                QTest::mouseClick(box->findChild<QPushButton *>(QStringLiteral("saveButton")),
                                  Qt::LeftButton, {}, QPoint(), mouseDelayMs);
            } else if (auto *dialog = qobject_cast<QFileDialog *>(modal)) {
                fileDialog = true;
                dialog->reject();
            }
        });
        hand.start();
        // Back to the window after the question (offscreen leaves no window active).
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        QTest::keyClick(m_window.get(), Qt::Key_O, Qt::ControlModifier);
        QTRY_VERIFY_WITH_TIMEOUT(saved && fileDialog, longWait);
        hand.stop();
        QVERIFY(!m_window->isWindowModified());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.readAll().contains("\"Sine\""));

        // Quitting with a change asks; Cancel keeps the window.
        QVERIFY(typeIntoCell(view, cellOf(table, QStringLiteral("R0"), WatchTableModel::NameColumn),
                             QStringLiteral("Scans")));
        QTRY_VERIFY(m_window->isWindowModified());
        UiTestUtil::answerModal([&] { m_window->close(); },
                                UiTestUtil::clickButton("cancelButton"));
        QVERIFY(m_window->isVisible());
    }

    // Beside the quality, the age of the value: small while polled, growing while the table is
    // paused; the late state carries it too. A single timer repaints the quality column only.
    void valueAgeBesideQuality()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R1"), 200, 2000);
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(allValues(model), longWait);
        QTableView *view = table->view();
        const QModelIndex quality
            = table->viewIndex(model->index(0, WatchTableModel::QualityColumn));
        QTRY_VERIFY2(quality.data().toString().startsWith(QStringLiteral("good, ")),
                     qPrintable(quality.data().toString()));
        const double fresh = ageSeconds(quality.data().toString());
        QVERIFY2(fresh >= 0 && fresh < 30, qPrintable(quality.data().toString()));
        // Shown whole in the cell.
        QVERIFY(view->columnWidth(WatchTableModel::QualityColumn)
                >= view->fontMetrics().horizontalAdvance(quality.data().toString()));

        // Paused: no values, the age grows on its own, without a reset.
        QSignalSpy resets(view->model(), &QAbstractItemModel::modelReset);
        auto *pause = table->findChild<QToolButton *>(QStringLiteral("pauseButton"));
        QVERIFY(onScreen(pause));
        QTest::mouseClick(pause, Qt::LeftButton, {}, QPoint(), mouseDelayMs);
        QTRY_VERIFY(table->isPaused());
        // The last value's highlight (a repaint of the value column) has ended.
        QTRY_VERIFY_WITH_TIMEOUT(
            !model->index(0, WatchTableModel::ValueColumn).data(Qt::BackgroundRole).isValid(),
            longWait);
        // ... and its repaint came (the highlight timer ticks more often than the age's).
        QSignalSpy settling(model, &QAbstractItemModel::dataChanged);
        QTRY_VERIFY_WITH_TIMEOUT(settling.count() >= 2, longWait);
        QSignalSpy changes(model, &QAbstractItemModel::dataChanged);
        QTRY_VERIFY_WITH_TIMEOUT(ageSeconds(quality.data().toString()) >= 2.0, longWait);
        QVERIFY2(quality.data().toString().startsWith(QStringLiteral("stale, ")),
                 qPrintable(quality.data().toString()));
        QVERIFY(changes.count() >= 3);
        for (const QList<QVariant> &args : std::as_const(changes)) {
            const auto from = args.at(0).value<QModelIndex>();
            const auto to = args.at(1).value<QModelIndex>();
            QCOMPARE(from.column(), int(WatchTableModel::QualityColumn));
            QCOMPARE(to.column(), int(WatchTableModel::QualityColumn));
        }
        QCOMPARE(resets.count(), 0);
        QTest::mouseClick(pause, Qt::LeftButton, {}, QPoint(), mouseDelayMs);
        QTRY_VERIFY_WITH_TIMEOUT(quality.data().toString().startsWith(QStringLiteral("good, ")),
                                 longWait);

        // Answers slower than twice the interval: late, with the age.
        FaultConfig slow;
        slow.latencyMs = 700;
        m_plc->server.setFaults(slow);
        QTRY_VERIFY2_WITH_TIMEOUT(quality.data().toString().startsWith(QStringLiteral("late, ")),
                                  qPrintable(quality.data().toString()), longWait);
        QVERIFY(ageSeconds(quality.data().toString()) >= 0);
    }

    // The age refresh repaints the rows on screen, not all 200: behind the sort/filter proxy
    // every repainted row is filtered again. Scrolled, the repaint follows the rows shown.
    void ageRepaintsOnlyRowsOnScreen()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R0..R199"), 200, 2000);
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_COMPARE_WITH_TIMEOUT(model->rowCount(), 200, longWait);
        QTRY_VERIFY_WITH_TIMEOUT(allValues(model), longWait);
        QTableView *view = table->view();
        auto *pause = table->findChild<QToolButton *>(QStringLiteral("pauseButton"));
        QVERIFY(onScreen(pause));
        QTest::mouseClick(pause, Qt::LeftButton, {}, QPoint(), mouseDelayMs);
        QTRY_VERIFY(table->isPaused());
        // Paused values turn stale (a change of every row's quality, not an age repaint).
        for (int r : {0, 199})
            QTRY_VERIFY_WITH_TIMEOUT(model->index(r, WatchTableModel::QualityColumn)
                                         .data()
                                         .toString()
                                         .startsWith(QStringLiteral("stale, ")),
                                     longWait);
        QTest::qWait(300);
        // A filter typed as a person would: the proxy now filters every row it is told changed.
        QLineEdit *filter = table->findChild<QLineEdit *>(QStringLiteral("filterEdit"));
        QVERIFY(onScreen(filter));
        QTest::mouseClick(filter, Qt::LeftButton, {}, QPoint(), mouseDelayMs);
        QTest::keyClicks(filter, QStringLiteral("R1"), {}, 40);
        QTRY_VERIFY(view->model()->rowCount() < 200);
        const int shown = view->model()->rowCount();
        QVERIFY(shown > 40); // R1, R10..R19, R100..R199: more than a screenful

        auto repainted = [&](int waitMs) {
            QSignalSpy changes(model, &QAbstractItemModel::dataChanged);
            QTest::qWait(waitMs);
            std::set<int> rows;
            for (const QList<QVariant> &args : std::as_const(changes)) {
                const auto from = args.at(0).value<QModelIndex>();
                const auto to = args.at(1).value<QModelIndex>();
                if (from.column() != WatchTableModel::QualityColumn)
                    continue;
                for (int r = from.row(); r <= to.row(); ++r)
                    rows.insert(r);
            }
            return rows;
        };
        auto onScreenRows = [&] {
            std::set<int> rows;
            const int first = view->rowAt(0);
            int last = view->rowAt(view->viewport()->height() - 1);
            if (last < 0)
                last = view->model()->rowCount() - 1;
            for (int r = first; r <= last; ++r)
                rows.insert(table->modelRow(view->model()->index(r, 0)));
            return rows;
        };
        view->scrollToTop(); // the rows just added were scrolled into view
        std::set<int> top = repainted(4 * WatchTableModel::ageRefreshMs);
        QVERIFY(!top.empty());
        QCOMPARE(top, onScreenRows());
        QVERIFY(int(top.size()) < shown);
        QVERIFY(top.count(model->rowCount() - 1) == 0);

        // End: the last rows (R199 among them) are the ones repainted now.
        view->setFocus();
        QTest::keyClick(view, Qt::Key_End, Qt::ControlModifier);
        QTest::qWait(100);
        const std::set<int> bottom = repainted(4 * WatchTableModel::ageRefreshMs);
        QCOMPARE(bottom, onScreenRows());
        QVERIFY(bottom.count(model->rowCount() - 1) == 1);
        QVERIFY(bottom != top);
    }

    // A register shown in hex is plotted as the number it holds: the sine's negative half
    // stays negative (not 65,000), and no axis label is cut to "…".
    void trendOfHexRegisterKeepsItsSign()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R1 R0"), 100);
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(allValues(model), longWait);
        QVERIFY(model->setFormat(0, DisplayFormat::Hex, false));
        TrendView *trend = addToTrend(table, {QStringLiteral("R1"), QStringLiteral("R0")});
        QVERIFY(trend);
        // The sine goes below zero within its 10 s period.
        const auto lowest = [trend] {
            double low = 1e9;
            const TrendBuffer &b = trend->buffer(0);
            for (qsizetype i = 0; i < b.size(); ++i)
                low = std::min(low, b.at(i).value);
            return low;
        };
        const auto highest = [trend] {
            double high = -1e9;
            const TrendBuffer &b = trend->buffer(0);
            for (qsizetype i = 0; i < b.size(); ++i)
                high = std::max(high, b.at(i).value);
            return high;
        };
        QTRY_VERIFY_WITH_TIMEOUT(lowest() < -100, 30000);
        QVERIFY2(highest() <= 1000, qPrintable(QString::number(highest())));
        QTRY_VERIFY_WITH_TIMEOUT(highest() > 100, 30000);

        // Labels cut to "…", with the trend under the table and beside it (its dock moved to the
        // right, narrow, as on a laptop with the table wanting the width).
        const auto cutLabels = [trend] {
            return cutChartLabels(trend);
        };
        trend->refresh();
        QTRY_COMPARE(cutLabels(), QString());
        auto *dock = m_window->findChild<QDockWidget *>(QStringLiteral("trendDock"));
        QVERIFY(dock);
        m_window->addDockWidget(Qt::RightDockWidgetArea, dock);
        dock->show();
        m_window->resizeDocks({dock}, {420}, Qt::Horizontal);
        QTRY_VERIFY(dock->isVisible() && dock->width() < 600);
        // The chart laid out again at the dock's width.
        QTRY_VERIFY(trend->chart()->plotArea().width() > 50
                    && trend->chart()->plotArea().width() < dock->width());
        trend->refresh();
        QCOMPARE(cutLabels(), QString());
    }

    // Four lines on separate axes (three analog scales and the bit axis) in a trend docked
    // beside the table and dragged as narrow as it goes: every axis label stays whole (the dock
    // stops where the labels would be cut), and the plot keeps room.
    void trendAxesStayWholeWhenNarrow()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R1 R0 DR10 Y0"), 100);
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_VERIFY_WITH_TIMEOUT(allValues(model), longWait);
        TrendView *trend = addToTrend(table, {QStringLiteral("R1"), QStringLiteral("R0"),
                                              QStringLiteral("DR10"), QStringLiteral("Y0")});
        QVERIFY(trend);
        auto *separate = trend->findChild<QAbstractButton *>(QStringLiteral("trendSeparateAxes"));
        QVERIFY(onScreen(separate));
        if (!separate->isChecked())
            QTest::mouseClick(separate, Qt::LeftButton, {}, QPoint(), mouseDelayMs);
        QTRY_VERIFY(separate->isChecked());
        QTRY_COMPARE(trend->valueAxes().size(), 4);
        QTest::qWait(1500); // ranges from a second of values

        auto *dock = m_window->findChild<QDockWidget *>(QStringLiteral("trendDock"));
        QVERIFY(dock);
        m_window->addDockWidget(Qt::RightDockWidgetArea, dock);
        dock->show();
        for (int width : {600, 420, 200}) {
            m_window->resizeDocks({dock}, {width}, Qt::Horizontal);
            QTest::qWait(300);
            trend->refresh();
            QTest::qWait(100);
            QVERIFY2(cutChartLabels(trend).isEmpty(),
                     qPrintable(QStringLiteral("dock %1 px wide: %2")
                                    .arg(dock->width())
                                    .arg(cutChartLabels(trend))));
            QVERIFY2(overlappingAxisLabels(trend).isEmpty(),
                     qPrintable(QStringLiteral("dock %1 px wide: %2")
                                    .arg(dock->width())
                                    .arg(overlappingAxisLabels(trend))));
            QVERIFY2(trend->chart()->plotArea().width() > 50,
                     qPrintable(QString::number(trend->chart()->plotArea().width())));
            QVERIFY(onScreen(separate));
        }
    }

    // At 1366x768 the table's columns fit, also with the forcing dock open beside it (Ctrl+Shift+F)
    // and with a wider font: no sideways scrolling, the comment column takes what is left.
    void columnsFitTheWindow()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R0 R1"));
        QVERIFY(table);
        QTRY_VERIFY_WITH_TIMEOUT(allValues(table->model()), longWait);
        QTableView *view = table->view();
        QVERIFY(onScreen(view));
        const auto fits = [view] {
            return view->horizontalHeader()->length() <= view->viewport()->width()
                   && !view->horizontalScrollBar()->isVisible();
        };
        QTRY_VERIFY(fits());
        QTest::keyClick(m_window.get(), Qt::Key_F, Qt::ControlModifier | Qt::ShiftModifier,
                        keyDelayMs);
        auto *forcing = m_window->findChild<QDockWidget *>(QStringLiteral("forcingDock"));
        QVERIFY(forcing);
        QTRY_VERIFY(forcing->isVisible());
        const auto widths = [view] {
            QStringList out;
            for (int c = 0; c < WatchTableModel::ColumnCount; ++c)
                out << QString::number(view->columnWidth(c));
            return QStringLiteral("columns %1 px, view %2 px")
                .arg(out.join(QLatin1Char(' ')))
                .arg(view->viewport()->width());
        };
        QTRY_VERIFY2(fits(), qPrintable(widths()));
        const int em = view->fontMetrics().horizontalAdvance(QLatin1Char('M'));
        QVERIFY(view->columnWidth(WatchTableModel::CommentColumn) >= 3 * em);
        // Every column but the comment keeps room for a few characters.
        for (int c = 0; c < WatchTableModel::CommentColumn; ++c)
            QVERIFY2(view->columnWidth(c) >= 3 * em, qPrintable(QString::number(c)));
    }
};

// A screen of a laptop's size: the offscreen platform reads it from a configuration file.
int main(int argc, char *argv[])
{
    const UiTestUtil::OffscreenScreen screen(laptop);
    if (!screen.isReady())
        return 1;
    QApplication app(argc, argv);
    TestUiTables test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_ui_tables.moc"
