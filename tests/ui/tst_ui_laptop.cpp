// The studio on a 1366x768 laptop (issue 34): the offscreen platform is given a screen of that
// size, the main window opens as on a first start, and every tool and dialog it offers is opened
// against the demo simulator (real, over loopback TCP). Every visible control must lie on the
// screen's available area and inside its own window, with no sideways scrolling; vertical
// scrolling of a tool dock is allowed.
#include "demowindow.h"
#include "testutil.h"
#include "ui/common/messageline.h"
#include "ui/connection/connection.h"
#include "ui/connection/connectiondialog.h"
#include "ui/connection/connectionmanager.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/trend/trendview.h"
#include "ui/watch/watchtablewidget.h"
#include "uitestutil.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QChart>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMainWindow>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QValueAxis>

using namespace Fatek;

namespace {

constexpr int longWait = 20000;
constexpr int keyDelayMs = 10;
const QSize laptop(1366, 768);

// A control a person looks at or clicks; the parts of composite widgets (a spin box's line edit,
// a view's headers) are checked through their owner.
bool isControl(const QWidget *w)
{
    for (const QWidget *p = w->parentWidget(); p; p = p->parentWidget()) {
        if (qobject_cast<const QAbstractSpinBox *>(p) || qobject_cast<const QComboBox *>(p)
            || qobject_cast<const QAbstractItemView *>(p))
            return false;
    }
    if (qobject_cast<const QScrollBar *>(w))
        return false;
    if (const auto *label = qobject_cast<const QLabel *>(w))
        return !label->text().isEmpty();
    return qobject_cast<const QAbstractButton *>(w) || qobject_cast<const QComboBox *>(w)
           || qobject_cast<const QAbstractSpinBox *>(w) || qobject_cast<const QLineEdit *>(w)
           || qobject_cast<const QAbstractItemView *>(w) || qobject_cast<const QProgressBar *>(w)
           || qobject_cast<const QTabBar *>(w) || qobject_cast<const MessageLine *>(w)
           || qobject_cast<const QStatusBar *>(w);
}

// A dock behind another dock's tab is not on screen by design.
bool behindATab(const QWidget *w)
{
    for (const QWidget *p = w; p; p = p->parentWidget()) {
        if (const auto *dock = qobject_cast<const QDockWidget *>(p)) {
            if (dock->visibleRegion().isEmpty())
                return true;
        }
    }
    return false;
}

// The scroll area whose viewport is `w`, if any.
const QScrollArea *scrollAreaOfViewport(const QWidget *w)
{
    const auto *area = w->parentWidget()
                           ? qobject_cast<const QScrollArea *>(w->parentWidget()->parentWidget())
                           : nullptr;
    return area && area->viewport() == w->parentWidget() ? area : nullptr;
}

// The controls of `top` that a person cannot see whole: off the available screen, outside the
// window, or cut by a parent (a tool dock's scroll area may cut them at the bottom or top only:
// it scrolls vertically, never sideways).
QStringList misplacedControls(QWidget *top)
{
    QStringList out;
    const QRect available = top->screen()->availableGeometry();
    if (!available.contains(top->frameGeometry()))
        out << QStringLiteral("window %1 frame %2,%3 %4x%5 is not inside the screen %6x%7")
                   .arg(top->objectName())
                   .arg(top->frameGeometry().x())
                   .arg(top->frameGeometry().y())
                   .arg(top->frameGeometry().width())
                   .arg(top->frameGeometry().height())
                   .arg(available.width())
                   .arg(available.height());
    const QList<QWidget *> widgets = top->findChildren<QWidget *>();
    for (QWidget *w : widgets) {
        if (!w->isVisible() || w->window() != top || !isControl(w) || behindATab(w))
            continue;
        // A main window keeps the tab bars of dock groups it does not use outside itself.
        if (qobject_cast<QTabBar *>(w) && qobject_cast<QMainWindow *>(w->parentWidget())
            && !w->geometry().intersects(w->parentWidget()->rect()))
            continue;
        const QString name
            = QStringLiteral("%1 \"%2\" (%3)")
                  .arg(QString::fromLatin1(w->metaObject()->className()), w->objectName(),
                       qobject_cast<QLabel *>(w) ? qobject_cast<QLabel *>(w)->text().left(30)
                       : qobject_cast<QAbstractButton *>(w)
                           ? qobject_cast<QAbstractButton *>(w)->text()
                           : QString());
        const QRect global(w->mapToGlobal(QPoint(0, 0)), w->size());
        if (!available.contains(global) || !top->geometry().contains(global)) {
            out << QStringLiteral("%1 at %2,%3 %4x%5 is off the screen or the window")
                       .arg(name)
                       .arg(global.x())
                       .arg(global.y())
                       .arg(global.width())
                       .arg(global.height());
            continue;
        }
        // Cut by a parent (a dock narrower than its tool, a scroll area scrolled sideways).
        // Inside a scroll area it may be below or above the part shown: it scrolls vertically.
        bool scrolls = false;
        for (QWidget *child = w, *p = w->parentWidget(); p && p != top;
             child = p, p = p->parentWidget()) {
            const QRect inParent(w->mapTo(p, QPoint(0, 0)), w->size());
            scrolls = scrolls || scrollAreaOfViewport(child) != nullptr;
            const bool fits = scrolls ? inParent.left() >= 0 && inParent.right() < p->width()
                                      : p->rect().contains(inParent);
            if (!fits) {
                out << QStringLiteral("%1 is cut by %2 \"%3\"")
                           .arg(name, QString::fromLatin1(p->metaObject()->className()),
                                p->objectName());
                break;
            }
        }
    }
    // Nothing needs a sideways scroll.
    for (QScrollArea *area : top->findChildren<QScrollArea *>()) {
        if (area->isVisible() && !behindATab(area) && area->horizontalScrollBar()->isVisible())
            out << QStringLiteral("%1 scrolls sideways").arg(area->objectName());
    }
    return out;
}

} // namespace

class TestUiLaptop : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_settingsDir;
    std::unique_ptr<MainWindow> m_window;

    // The window as on a first start, with the demo PLC connected and its table polling.
    bool openDemo() { return UiTestUtil::openDemoWindow(m_window, false, longWait); }

    static QString report(const QStringList &problems)
    {
        return problems.join(QStringLiteral("\n  "));
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_laptop"));
        QCOMPARE(QGuiApplication::primaryScreen()->availableGeometry().size(), laptop);
    }

    void cleanup()
    {
        // Each case starts as a first start: no geometry or dock layout saved.
        m_window.reset();
        QSettings().clear();
    }

    // The first window fits the screen: the status bar with the link state is on it.
    void firstWindowFitsTheScreen()
    {
        QVERIFY(openDemo());
        QVERIFY2(misplacedControls(m_window.get()).isEmpty(),
                 qPrintable(report(misplacedControls(m_window.get()))));
        QVERIFY(m_window->statusBar()->isVisible());
    }

    // A window saved on a larger screen comes back inside this one.
    void savedGeometryComesBackInside()
    {
        {
            MainWindow larger;
            larger.show();
            QVERIFY(QTest::qWaitForWindowExposed(&larger));
            larger.setGeometry(300, 200, 1800, 1100);
            QTRY_COMPARE(larger.size(), QSize(1800, 1100));
            larger.close();
        }
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QVERIFY2(misplacedControls(m_window.get()).isEmpty(),
                 qPrintable(report(misplacedControls(m_window.get()))));
    }

    // Every tool and dialog the window offers, opened as a person opens it.
    void everyToolFits_data()
    {
        QTest::addColumn<QString>("tool");
        for (const char *tool : {"control", "forcing", "console", "trend", "loopback", "program",
                                 "snapshot", "checkout", "stations"})
            QTest::newRow(tool) << QString::fromLatin1(tool);
    }
    void everyToolFits()
    {
        QFETCH(QString, tool);
        QVERIFY(openDemo());
        QWidget *opened = nullptr;
        if (tool == QLatin1String("stations")) {
            auto *action = m_window->findChild<QAction *>(QStringLiteral("scanStationsAction"));
            QVERIFY(action);
            action->trigger();
            opened = m_window->findChild<QDialog *>(QStringLiteral("stationScanDialog"));
        } else {
            opened = m_window->openTool(tool);
        }
        QVERIFY(opened);
        QWidget *top = opened->window();
        QVERIFY(QTest::qWaitForWindowExposed(top));
        QTest::qWait(1500); // first answers, messages
        QVERIFY2(misplacedControls(top).isEmpty(), qPrintable(report(misplacedControls(top))));
        if (top != m_window.get())
            QVERIFY2(misplacedControls(m_window.get()).isEmpty(),
                     qPrintable(report(misplacedControls(m_window.get()))));
    }

    // Forcing dock: Scan and Enable all stay reachable, the dock does not widen after scan
    // messages (long ones wrap or elide, with the whole text in the tooltip).
    void forcingDockKeepsItsWidth()
    {
        QVERIFY(openDemo());
        QWidget *panel = m_window->openTool(QStringLiteral("forcing"));
        QVERIFY(panel);
        auto *dock = m_window->findChild<QDockWidget *>(QStringLiteral("forcingDock"));
        QVERIFY(dock);
        QTest::qWait(500); // the dock opens as wide as the panel needs
        auto *tabs = panel->findChild<QTabWidget *>();
        QVERIFY(tabs);
        QTest::mouseClick(tabs->tabBar(), Qt::LeftButton, {}, tabs->tabBar()->tabRect(1).center());
        QTRY_COMPARE(tabs->currentIndex(), 1);
        const int width = dock->width();
        const int panelWidth = panel->width();
        auto *scan = panel->findChild<QPushButton *>(QStringLiteral("scanButton"));
        auto *ranges = panel->findChild<QLineEdit *>(QStringLiteral("forcedRanges"));
        auto *message = panel->findChild<MessageLine *>(QStringLiteral("forcedMessage"));
        QVERIFY(scan && ranges && message);
        for (const QString &typed :
             {QString(), QStringLiteral("X0-255, Y0-255, M0-1999, S0-999, T0-255, C0-255")}) {
            QTest::mouseClick(ranges, Qt::LeftButton);
            ranges->clear();
            QTest::keyClicks(ranges, typed, {}, keyDelayMs);
            QTest::mouseClick(scan, Qt::LeftButton);
            QTRY_VERIFY_WITH_TIMEOUT(message->text().startsWith(QStringLiteral("Scanned")),
                                     longWait);
            QTest::qWait(200);
            QCOMPARE(dock->width(), width);
            QCOMPARE(panel->width(), panelWidth);
            QCOMPARE(message->toolTip(), message->text());
            QVERIFY2(misplacedControls(m_window.get()).isEmpty(),
                     qPrintable(report(misplacedControls(m_window.get()))));
        }
    }

    // Raw console: a frame typed and sent, its answer readable without dragging the splitter.
    void consoleShowsSendLineAndAnswer()
    {
        QVERIFY(openDemo());
        auto *console = m_window->openTool(QStringLiteral("console"));
        QVERIFY(console);
        QLabel *result = UiTestUtil::sendRawFrame(console, QStringLiteral("30 31 34 30"));
        QVERIFY(result);
        auto *input = console->findChild<QLineEdit *>(QStringLiteral("sendInput"));
        auto *send = console->findChild<QPushButton *>(QStringLiteral("sendButton"));
        QTRY_VERIFY_WITH_TIMEOUT(result->text().contains(QStringLiteral("Answer")), longWait);
        QTest::qWait(200);
        auto *scroll = m_window->findChild<QScrollArea *>(QStringLiteral("rawConsoleDockScroll"));
        QVERIFY(scroll);
        for (QWidget *w : {static_cast<QWidget *>(input), static_cast<QWidget *>(send),
                           static_cast<QWidget *>(result)}) {
            const QRect shown(w->mapTo(scroll->viewport(), QPoint(0, 0)), w->size());
            QVERIFY2(scroll->viewport()->rect().contains(shown),
                     qPrintable(QStringLiteral("%1 at y %2..%3, the console shows 0..%4")
                                    .arg(w->objectName())
                                    .arg(shown.top())
                                    .arg(shown.bottom())
                                    .arg(scroll->viewport()->height())));
        }
    }

    // Raw console opened with its shortcut on a laptop: several rows of traffic under its
    // controls (it showed one at 800 px), and the watch table keeps rows of its own.
    void consoleShowsTrafficRows()
    {
        QVERIFY(openDemo());
        QTest::keyClick(m_window.get(), Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
        auto *dock = m_window->findChild<QDockWidget *>(QStringLiteral("rawConsoleDock"));
        QVERIFY(dock);
        QTRY_VERIFY(dock->isVisible() && !dock->visibleRegion().isEmpty());
        auto *traffic = dock->findChild<QTableView *>(QStringLiteral("trafficView"));
        QVERIFY(traffic);
        QTRY_VERIFY_WITH_TIMEOUT(traffic->model()->rowCount() >= 8, longWait);
        QTest::qWait(200);
        const int rowHeight = traffic->verticalHeader()->defaultSectionSize();
        QVERIFY2(traffic->viewport()->height() >= 5 * rowHeight,
                 qPrintable(QStringLiteral("traffic shows %1 px, a row is %2 px")
                                .arg(traffic->viewport()->height())
                                .arg(rowHeight)));
        auto *scroll = m_window->findChild<QScrollArea *>(QStringLiteral("rawConsoleDockScroll"));
        QVERIFY(scroll);
        const QRect shown(traffic->mapTo(scroll->viewport(), QPoint(0, 0)), traffic->size());
        QVERIFY2(scroll->viewport()->rect().contains(shown),
                 qPrintable(QStringLiteral("the traffic at y %1..%2, the console shows 0..%3")
                                .arg(shown.top())
                                .arg(shown.bottom())
                                .arg(scroll->viewport()->height())));
        auto *watch = m_window->centralWidget()->findChild<QTableView *>();
        QVERIFY(watch);
        QVERIFY2(
            watch->viewport()->height() >= 5 * watch->verticalHeader()->defaultSectionSize(),
            qPrintable(
                QStringLiteral("the watch table shows %1 px").arg(watch->viewport()->height())));
        QVERIFY2(misplacedControls(m_window.get()).isEmpty(),
                 qPrintable(report(misplacedControls(m_window.get()))));
    }

    // Program dialog: a sensible size that stays while it works; its title is not cut.
    void programDialogKeepsItsSize()
    {
        QVERIFY(openDemo());
        auto *dialog = qobject_cast<QDialog *>(m_window->openTool(QStringLiteral("program")));
        QVERIFY(dialog);
        QVERIFY(QTest::qWaitForWindowExposed(dialog));
        const QSize size = dialog->size();
        const int title = dialog->fontMetrics().horizontalAdvance(dialog->windowTitle());
        // The title bar also holds the icon and the window buttons.
        QVERIFY2(
            dialog->width() >= title + 150,
            qPrintable(QStringLiteral("%1 px for a %2 px title").arg(dialog->width()).arg(title)));
        auto *label = dialog->findChild<QLabel *>(QStringLiteral("progressLabel"));
        QVERIFY(label);
        label->setText(QStringLiteral("Verifying what was written: 207 of 207 pages, about "
                                      "1000 s left, and some more words for a long language"));
        QTest::qWait(100);
        QCOMPARE(dialog->size(), size);
        QVERIFY2(misplacedControls(dialog).isEmpty(),
                 qPrintable(report(misplacedControls(dialog))));
    }

    // Issue 54: the trend at a laptop's height keeps a useful plot (it was about 100 px, one
    // label per value axis), whole axis titles, and the table keeps rows of its own.
    void trendKeepsAUsefulPlot()
    {
        QVERIFY(openDemo());
        auto *trend = qobject_cast<TrendView *>(m_window->openTool(QStringLiteral("trend")));
        QVERIFY(trend);
        QTRY_VERIFY_WITH_TIMEOUT(trend->itemCount() >= 2, longWait);
        QTest::qWait(500); // laid out, grown
        const double plot = trend->chart()->plotArea().height();
        QVERIFY2(plot >= trend->usefulPlotHeight(),
                 qPrintable(QStringLiteral("the plot is %1 px tall, %2 px wanted")
                                .arg(plot)
                                .arg(trend->usefulPlotHeight())));
        for (QValueAxis *axis : trend->valueAxes()) {
            QVERIFY2(TrendView::tickValues(axis).size() >= 3,
                     qPrintable(QStringLiteral("%1: %2 labels")
                                    .arg(axis->titleText())
                                    .arg(TrendView::tickValues(axis).size())));
            const int title = QFontMetrics(axis->titleFont()).horizontalAdvance(axis->titleText());
            QVERIFY2(!axis->isTitleVisible() || title <= plot,
                     qPrintable(QStringLiteral("title \"%1\" is %2 px on a %3 px plot")
                                    .arg(axis->titleText())
                                    .arg(title)
                                    .arg(plot)));
        }
        auto *watch = m_window->currentWatchTable()->view();
        QVERIFY2(
            watch->viewport()->height() >= 5 * watch->verticalHeader()->defaultSectionSize(),
            qPrintable(
                QStringLiteral("the watch table shows %1 px").arg(watch->viewport()->height())));
    }

    // Snapshot dialog: a Close button that closes it.
    void snapshotDialogCloses()
    {
        QVERIFY(openDemo());
        QPointer<QWidget> dialog = m_window->openTool(QStringLiteral("snapshot"));
        QVERIFY(dialog);
        QVERIFY(QTest::qWaitForWindowExposed(dialog));
        auto *box = dialog->findChild<QDialogButtonBox *>();
        QVERIFY2(box, "no button box");
        QPushButton *close = box->button(QDialogButtonBox::Close);
        QVERIFY(close && close->isVisible());
        QTest::mouseClick(close, Qt::LeftButton);
        QTRY_VERIFY(!dialog || !dialog->isVisible());
    }

    // Connection dialog: TCP's two fields, then Protocol right below them (no room kept for the
    // serial page's six rows).
    void connectionDialogHasNoGap()
    {
        QVERIFY(openDemo());
        bool checked = false;
        bool gatewayFits = false;
        QTimer hand;
        hand.setInterval(50);
        connect(&hand, &QTimer::timeout, this, [&] {
            auto *dialog = qobject_cast<QDialog *>(QApplication::activeModalWidget());
            if (!dialog)
                return;
            hand.stop();
            auto *kind = dialog->findChild<QComboBox *>(QStringLiteral("linkKindCombo"));
            auto *form = dialog->findChild<QFormLayout *>();
            if (kind && form) {
                kind->setCurrentIndex(kind->findText(QStringLiteral("TCP")));
                QTest::qWait(100);
                QWidget *port = nullptr;
                QWidget *protocol = nullptr;
                for (QSpinBox *spin : dialog->findChildren<QSpinBox *>()) {
                    if (spin->isVisible() && spin->maximum() == 65535)
                        port = spin;
                }
                for (QComboBox *combo : dialog->findChildren<QComboBox *>()) {
                    if (combo->findText(QStringLiteral("Auto-detect")) >= 0)
                        protocol = combo;
                }
                if (port && protocol) {
                    const int gap = protocol->mapTo(dialog, QPoint(0, 0)).y()
                                    - port->mapTo(dialog, QPoint(0, port->height())).y();
                    qInfo("gap between Port and Protocol: %d px", gap);
                    checked = gap <= 2 * form->verticalSpacing() + 6
                              && misplacedControls(dialog).isEmpty();
                    if (!misplacedControls(dialog).isEmpty())
                        qWarning("%s", qPrintable(report(misplacedControls(dialog))));
                }
                // The gateway page, the tallest (broker, names, three TLS files), fits too.
                kind->setCurrentIndex(kind->findData(ConnectionDialog::gatewayKind));
                QTest::qWait(100);
                auto *key = dialog->findChild<QLineEdit *>(QStringLiteral("brokerKeyEdit"));
                gatewayFits = key && key->isVisible() && misplacedControls(dialog).isEmpty();
                if (!misplacedControls(dialog).isEmpty())
                    qWarning("%s", qPrintable(report(misplacedControls(dialog))));
            }
            dialog->reject();
        });
        hand.start();
        QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(checked);
        QVERIFY(gatewayFits);
    }
};

// A screen of a laptop's size: the offscreen platform reads it from a configuration file.
int main(int argc, char *argv[])
{
    const UiTestUtil::OffscreenScreen screen(laptop);
    if (!screen.isReady())
        return 1;
    QApplication app(argc, argv);
    TestUiLaptop test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_ui_laptop.moc"
