// Issue 54, the studio in a person's hands (round three), on a 1366x768 laptop screen (its own
// main gives the offscreen platform that screen), done with the keys and clicks a person uses,
// against simulated PLCs over loopback TCP:
// - item 2: Ctrl+F4 closes a watch table at once, as a browser closes a tab, and Ctrl+Shift+T
//   (Watch > Reopen Closed Table) brings it back with its rows, names, settings and connection;
// - item 3: a memory snapshot taken and not saved asks before Esc, Close or quitting drops it;
// - item 4: adding a connection does not retarget PLC Control: STOP stops the PLC its dock names;
// - item 8: Help > User Guide (F1) shows the docs offline, Help > Keyboard Shortcuts lists every
//   shortcut of the window's actions.
// Screenshots of each place go to /tmp/tst_ui_nolostwork-*.png.
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "runningfbs.h"
#include "testutil.h"
#include "ui/connection/connection.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/tools/snapshotdialog.h"
#include "ui/watch/watchtablemodel.h"
#include "uitestutil.h"

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTimer>

#include <memory>

using namespace Fatek;
using UiTestUtil::answerModal;
using UiTestUtil::clickButton;

namespace {

constexpr int longWait = 20000;
const QSize laptop(1366, 768);

using Plc = RunningFbs;

SavedConnection savedFor(quint16 port, const QString &name)
{
    SavedConnection saved;
    saved.name = name;
    saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), port);
    saved.settings.timeoutMs = 500;
    saved.station = 1;
    return saved;
}

void saveShot(QWidget *widget, const QString &name)
{
    const QString path = QStringLiteral("/tmp/tst_ui_nolostwork-%1.png").arg(name);
    if (!widget->grab().save(path))
        qWarning("cannot write %s", qPrintable(path));
}

// Opens the menu bar's menu `title` with a click and clicks its action `objectName` (or only
// opens it when `objectName` is empty, and returns it open).
QMenu *clickMenu(QMainWindow *window, const QString &title, const char *objectName)
{
    QMenuBar *bar = window->menuBar();
    for (QAction *top : bar->actions()) {
        if (!top->menu() || top->text().remove(QLatin1Char('&')) != title)
            continue;
        QTest::mouseClick(bar, Qt::LeftButton, {}, bar->actionGeometry(top).center());
        QMenu *menu = top->menu();
        if (!QTest::qWaitFor([menu] { return menu->isVisible(); }, 5000))
            return nullptr;
        if (!objectName)
            return menu;
        for (QAction *a : menu->actions()) {
            if (a->objectName() == QLatin1String(objectName)) {
                QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(a).center());
                return menu;
            }
        }
        menu->close();
        return nullptr;
    }
    return nullptr;
}

// Fails the test if a modal question shows up while `action` runs (and answers it with Esc).
bool noQuestionDuring(const std::function<void()> &action)
{
    bool asked = false;
    QTimer escape;
    escape.setInterval(50);
    QObject::connect(&escape, &QTimer::timeout, &escape, [&] {
        if (QWidget *modal = QApplication::activeModalWidget()) {
            asked = true;
            QTest::keyClick(modal, Qt::Key_Escape);
        }
    });
    escape.start();
    action();
    QTest::qWait(300);
    return !asked;
}

} // namespace

class TestUiNoLostWork : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;
    std::unique_ptr<MainWindow> m_window;

    MainWindow *openWindow()
    {
        m_window = std::make_unique<MainWindow>();
        m_window->resize(laptop);
        m_window->show();
        m_window->activateWindow();
        if (!QTest::qWaitForWindowActive(m_window.get()))
            qWarning("the window is not active");
        return m_window.get();
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_nolostwork"));
    }

    void cleanup()
    {
        // A window kept open by an unanswered question must not block the next test.
        if (m_window) {
            for (auto *frame : m_window->findChildren<SnapshotDialog *>())
                frame->setConfirmer([](const QString &) { return true; });
        }
        m_window.reset();
    }

    // Item 2: Ctrl+F4 closes a table of named rows at once, and Ctrl+Shift+T brings it back
    // whole (rows, names, interval, write confirmation, connection, its place among the tabs).
    void closedTableReopens()
    {
        Plc plc;
        MainWindow *window = openWindow();
        Connection *c
            = window->openConnection(savedFor(plc.port, QStringLiteral("Press 1")), false);
        WatchTableWidget *pumps = window->currentWatchTable();
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        WatchTableSpec spec;
        spec.name = QStringLiteral("Pumps");
        spec.intervalMs = 750;
        spec.confirmWrites = false;
        for (int i = 0; i < 6; ++i) {
            WatchItemSpec item;
            item.address = TestUtil::addr(qPrintable(QStringLiteral("R%1").arg(i)));
            item.station = 1;
            item.name = QStringLiteral("Pump %1 speed").arg(i + 1);
            spec.items << item;
        }
        pumps->setSpec(spec);
        pumps->setConnection(c);
        window->addWatchTable(QStringLiteral("Other"));
        auto *tabs = window->findChild<QTabWidget *>(QStringLiteral("watchTabs"));
        tabs->setCurrentIndex(0);
        QCOMPARE(window->currentWatchTable(), pumps);
        const WatchTableSpec before = pumps->spec();

        QVERIFY(
            noQuestionDuring([&] { QTest::keyClick(window, Qt::Key_F4, Qt::ControlModifier); }));
        QCOMPARE(tabs->count(), 1);
        const QString told = window->statusBar()->currentMessage();
        QVERIFY2(told.contains(QStringLiteral("Pumps")) && told.contains(QStringLiteral("6 row"))
                     && told.contains(QStringLiteral("Ctrl+Shift+T")),
                 qPrintable(told));
        saveShot(window, QStringLiteral("table-closed"));
        QMenu *watch = clickMenu(window, QStringLiteral("Watch"), nullptr);
        QVERIFY(watch);
        auto *reopen = window->findChild<QAction *>(QStringLiteral("reopenClosedTableAction"));
        QVERIFY2(reopen, "Watch > Reopen Closed Table");
        QVERIFY(watch->actions().contains(reopen));
        QVERIFY(reopen->isEnabled());
        QCOMPARE(reopen->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T));
        saveShot(watch, QStringLiteral("watch-menu"));
        watch->close();

        QTest::keyClick(window, Qt::Key_T, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_COMPARE(tabs->count(), 2);
        WatchTableWidget *back = window->currentWatchTable();
        QCOMPARE(tabs->indexOf(back), 0);
        QCOMPARE(tabs->tabText(0), QStringLiteral("Pumps"));
        QCOMPARE(back->spec(), before);
        QCOMPARE(back->model()->item(2).name, QStringLiteral("Pump 3 speed"));
        QCOMPARE(back->connection(), c);
        QVERIFY(!reopen->isEnabled()); // nothing more to reopen
    }

    // Item 3: a snapshot taken and not saved asks before Esc, the main window's close and Close
    // drop it; Cancel keeps it, Save writes it, Discard drops it.
    void unsavedSnapshotAsks()
    {
        Plc plc;
        MainWindow *window = openWindow();
        Connection *c
            = window->openConnection(savedFor(plc.port, QStringLiteral("Press 1")), false);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        QVERIFY(clickMenu(window, QStringLiteral("Tools"), "memorySnapshotAction"));
        SnapshotDialog *dialog = nullptr;
        QTRY_VERIFY((dialog = window->findChild<SnapshotDialog *>()) && dialog->isVisible());
        QVERIFY(QTest::qWaitForWindowActive(dialog));
        auto *ranges = dialog->findChild<QLineEdit *>(QStringLiteral("ranges"));
        QTest::mouseClick(ranges, Qt::LeftButton);
        QTest::keyClicks(ranges, QStringLiteral("R0..R99, M0..M63"));
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("takeButton")),
                          Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(dialog->snapshot().has_value() && !dialog->isBusy(), longWait);
        QCOMPARE(dialog->snapshot()->values.size(), std::size_t(164));

        // Esc: the question; Cancel keeps the dialog and its snapshot.
        QString question = answerModal([&] { QTest::keyClick(dialog, Qt::Key_Escape); },
                                       clickButton("cancelButton"));
        QVERIFY2(question.contains(QStringLiteral("164 value")), qPrintable(question));
        QVERIFY(dialog->isVisible());
        QVERIFY(dialog->snapshot().has_value());

        // Quitting the main window asks the same, in front; Cancel keeps both open.
        question = answerModal([&] { window->close(); },
                               [&](QWidget *modal) {
                                   saveShot(modal, QStringLiteral("snapshot-question"));
                                   clickButton("cancelButton")(modal);
                               });
        QVERIFY2(question.contains(QStringLiteral("not saved")), qPrintable(question));
        QVERIFY(window->isVisible());
        QVERIFY(dialog->isVisible());

        // Close: Save… writes it (the file dialog answered by the test), then the dialog goes.
        const QString file = m_settingsDir.filePath(QStringLiteral("before.json"));
        dialog->setFileChooser([file](const ToolDialogFrame::FileQuestion &) { return file; });
        auto *box = dialog->findChild<QDialogButtonBox *>();
        QPushButton *close = box->button(QDialogButtonBox::Close);
        const QPointer<SnapshotDialog> shownDialog(dialog);
        answerModal([&] { QTest::mouseClick(close, Qt::LeftButton); }, clickButton("saveButton"));
        QTRY_VERIFY(!shownDialog || !shownDialog->isVisible());
        QVERIFY(QFileInfo::exists(file));
    }

    // Item 3, the other answer: Discard lets Esc drop the snapshot.
    void discardedSnapshotGoes()
    {
        Plc plc;
        MainWindow *window = openWindow();
        Connection *c
            = window->openConnection(savedFor(plc.port, QStringLiteral("Press 1")), false);
        QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
        QVERIFY(clickMenu(window, QStringLiteral("Tools"), "memorySnapshotAction"));
        SnapshotDialog *dialog = nullptr;
        QTRY_VERIFY((dialog = window->findChild<SnapshotDialog *>()) && dialog->isVisible());
        auto *ranges = dialog->findChild<QLineEdit *>(QStringLiteral("ranges"));
        QTest::mouseClick(ranges, Qt::LeftButton);
        QTest::keyClicks(ranges, QStringLiteral("R0..R9"));
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("takeButton")),
                          Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(dialog->snapshot().has_value() && !dialog->isBusy(), longWait);
        const QPointer<SnapshotDialog> shownDialog(dialog);
        const QString question = answerModal([&] { QTest::keyClick(dialog, Qt::Key_Escape); },
                                             clickButton("discardButton"));
        QVERIFY2(question.contains(QStringLiteral("not saved")), qPrintable(question));
        QTRY_VERIFY(!shownDialog || !shownDialog->isVisible());
    }

    // Item 4: PLC Control acts on the PLC of the table in front; a connection added later does
    // not retarget it, and STOP stops the PLC its dock and its label name, not the new one.
    void addedConnectionDoesNotRetargetTools()
    {
        Plc first;
        Plc second;
        MainWindow *window = openWindow();
        Connection *a
            = window->openConnection(savedFor(first.port, QStringLiteral("Press 1")), false);
        QTRY_COMPARE_WITH_TIMEOUT(a->linkState(), LinkState::Connected, longWait);
        QCOMPARE(window->currentWatchTable()->connection(), a);
        QTest::keyClick(window, Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
        auto *dock = window->findChild<QDockWidget *>(QStringLiteral("plcControlDock"));
        QTRY_VERIFY(dock->isVisible());
        auto *target = dock->findChild<QLabel *>(QStringLiteral("targetLabel"));
        QTRY_VERIFY2(target->text().contains(QStringLiteral("Press 1")),
                     qPrintable(target->text()));

        Connection *b
            = window->openConnection(savedFor(second.port, QStringLiteral("Press 2")), false);
        QTRY_COMPARE_WITH_TIMEOUT(b->linkState(), LinkState::Connected, longWait);
        QTest::qWait(300);
        QVERIFY2(target->text().contains(QStringLiteral("Press 1")), qPrintable(target->text()));
        QVERIFY2(dock->windowTitle().contains(QStringLiteral("Press 1")),
                 qPrintable(dock->windowTitle()));
        saveShot(window, QStringLiteral("control-target"));

        auto *stop = dock->findChild<QPushButton *>(QStringLiteral("stopButton"));
        QTRY_VERIFY(stop->isEnabled());
        const QString question
            = answerModal([&] { QTest::mouseClick(stop, Qt::LeftButton); },
                          [](QWidget *modal) {
                              auto *box = qobject_cast<QMessageBox *>(modal);
                              QTest::mouseClick(box->button(QMessageBox::Yes), Qt::LeftButton);
                          });
        QVERIFY2(question.contains(QStringLiteral("Press 1")), qPrintable(question));
        QTRY_VERIFY_WITH_TIMEOUT(!first.plc.isRunning(), longWait);
        QVERIFY(second.plc.isRunning());

        // A table on the second PLC in front: now the tools name and act on it.
        WatchTableWidget *other = window->addWatchTable(QStringLiteral("Line 2"));
        other->setConnection(b);
        auto *tabs = window->findChild<QTabWidget *>(QStringLiteral("watchTabs"));
        QTest::mouseClick(tabs->tabBar(), Qt::LeftButton, {},
                          tabs->tabBar()->tabRect(tabs->indexOf(other)).center());
        QTRY_VERIFY2(target->text().contains(QStringLiteral("Press 2")),
                     qPrintable(target->text()));
        QVERIFY2(dock->windowTitle().contains(QStringLiteral("Press 2")),
                 qPrintable(dock->windowTitle()));
    }

    // Item 8: F1 opens the user guide (built in: no network, no installed files), its links
    // lead on; Help > Keyboard Shortcuts lists every shortcut the window's actions have.
    void helpHasGuideAndShortcuts()
    {
        MainWindow *window = openWindow();
        QTest::keyClick(window, Qt::Key_F1);
        QDialog *guide = nullptr;
        QTRY_VERIFY((guide = window->findChild<QDialog *>(QStringLiteral("userGuideDialog")))
                    && guide->isVisible());
        auto *browser = guide->findChild<QTextBrowser *>(QStringLiteral("guideBrowser"));
        QVERIFY(browser);
        QVERIFY2(browser->toPlainText().contains(QStringLiteral("FATEK Studio documentation")),
                 qPrintable(browser->toPlainText().left(200)));
        // Click the link "Forcing discretes" where it shows: its page, with its screenshot.
        QTextCursor link = browser->document()->find(QStringLiteral("Forcing discretes"));
        QVERIFY(!link.isNull());
        link.setPosition(link.selectionStart() + 2);
        QTest::mouseClick(browser->viewport(), Qt::LeftButton, {},
                          browser->cursorRect(link).center());
        QTRY_VERIFY2(browser->source().path().endsWith(QStringLiteral("/guide/forcing.md")),
                     qPrintable(browser->source().toString()));
        QVERIFY2(browser->toPlainText().contains(QStringLiteral("Forcing")),
                 qPrintable(browser->toPlainText().left(200)));
        saveShot(guide, QStringLiteral("user-guide"));
        // Back to the contents, on to the GUI page.
        QTest::mouseClick(guide->findChild<QWidget *>(QStringLiteral("backButton")),
                          Qt::LeftButton);
        QTRY_VERIFY(browser->toPlainText().contains(QStringLiteral("FATEK Studio documentation")));
        link = browser->document()->find(QStringLiteral("GUI internals"));
        QVERIFY(!link.isNull());
        link.setPosition(link.selectionStart() + 2);
        QTest::mouseClick(browser->viewport(), Qt::LeftButton, {},
                          browser->cursorRect(link).center());
        QTRY_VERIFY(browser->toPlainText().contains(QStringLiteral("fatek-studio --demo")));
        saveShot(guide, QStringLiteral("user-guide-gui"));
        guide->close();

        QVERIFY(clickMenu(window, QStringLiteral("Help"), "shortcutListAction"));
        QDialog *list = nullptr;
        QTRY_VERIFY((list = window->findChild<QDialog *>(QStringLiteral("shortcutListDialog")))
                    && list->isVisible());
        auto *table = list->findChild<QTableWidget *>(QStringLiteral("shortcutTable"));
        QVERIFY(table);
        QMultiHash<QString, QString> rows; // keys -> action
        for (int r = 0; r < table->rowCount(); ++r)
            rows.insert(table->item(r, 0)->text(), table->item(r, 1)->text());
        // Every shortcut of every action the window has is listed with its action's name.
        int checked = 0;
        for (const QAction *a : window->findChildren<QAction *>()) {
            for (const QKeySequence &keys : a->shortcuts()) {
                if (keys.isEmpty() || a->text().isEmpty())
                    continue;
                const QString k = keys.toString(QKeySequence::NativeText);
                QVERIFY2(rows.contains(k), qPrintable(k + QStringLiteral(": ") + a->text()));
                ++checked;
            }
        }
        QVERIFY(checked >= 15);
        QVERIFY(rows.values(QStringLiteral("Ctrl+Shift+T"))
                    .contains(QStringLiteral("Reopen Closed Table")));
        QVERIFY(rows.values(QStringLiteral("F1")).contains(QStringLiteral("User Guide")));
        QVERIFY(
            rows.values(QStringLiteral("Ctrl+Shift+N")).contains(QStringLiteral("New Connection")));
        saveShot(list, QStringLiteral("shortcuts"));
    }
};

int main(int argc, char *argv[])
{
    const UiTestUtil::OffscreenScreen screen(laptop);
    if (!screen.isReady())
        return 1;
    QApplication app(argc, argv);
    TestUiNoLostWork test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_ui_nolostwork.moc"
