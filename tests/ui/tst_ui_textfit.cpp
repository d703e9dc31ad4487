// Issue 54, item 5: no text is cut. The main window, maximized on a 1366x768 laptop (and on a
// 1280x720 screen at 125 %: run with --small and QT_SCALE_FACTOR=1.25), runs the demo PLC (real,
// over loopback TCP); every dock, tool and dialog it offers is opened, and every label, button,
// group box, combo box, message line, table cell, status bar message and dialog title is measured
// against its rectangle (QFontMetrics::horizontalAdvance against contentsRect, word wrap and
// elision accounted for): a text wider than its place fails, unless it is elided on purpose with
// the whole text in its tooltip (a narrow table column).
#include "core/sim/modelprofile.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "demowindow.h"
#include "testutil.h"
#include "ui/common/messageline.h"
#include "ui/common/toolconfirmation.h"
#include "ui/connection/connection.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/tools/checkoutdetailsdialog.h"
#include "ui/tools/checkoutpunchdialog.h"
#include "ui/tools/iocheckoutdialog.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtablewidget.h"
#include "uitestutil.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDockWidget>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTextDocumentFragment>
#include <QTimer>
#include <QToolButton>

using namespace Fatek;

namespace {

constexpr int longWait = 20000;
bool smallScreen = false; // 1280x720 at 125 %

// The window's title bar holds the icon and the window buttons beside the title, and the window
// system adds the application's name.
constexpr int titleBarExtras = 150;

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

QString plainText(const QString &text)
{
    return Qt::mightBeRichText(text) ? QTextDocumentFragment::fromHtml(text).toPlainText() : text;
}

int widestLine(const QFontMetrics &fm, const QString &text)
{
    int widest = 0;
    for (const QString &line : text.split(QLatin1Char('\n')))
        widest = std::max(widest, fm.horizontalAdvance(line));
    return widest;
}

QString nameOf(const QWidget *w, const QString &text)
{
    return QStringLiteral("%1 \"%2\" (%3)")
        .arg(QString::fromLatin1(w->metaObject()->className()), w->objectName(), text.left(60));
}

// The cells of a table that are cut without their whole text in the tooltip.
QStringList cutCells(const QTableView *view)
{
    QStringList out;
    const QAbstractItemModel *model = view->model();
    if (!model)
        return out;
    const QFontMetrics fm = view->fontMetrics();
    const int first = std::max(0, view->rowAt(0));
    const int last = view->rowAt(view->viewport()->height() - 1);
    for (int r = first; r <= (last < 0 ? model->rowCount() - 1 : last); ++r) {
        for (int c = 0; c < model->columnCount(); ++c) {
            if (view->isColumnHidden(c))
                continue;
            const QModelIndex index = model->index(r, c);
            const QString text = index.data().toString();
            if (text.isEmpty() || text.contains(QLatin1Char('\n')))
                continue;
            // The item's text margins (QCommonStyle: the focus frame's margin and one pixel, on
            // each side), and room for an icon or a check box.
            const int margin
                = view->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, view) + 1;
            int room = view->columnWidth(c) - 2 * margin;
            if (!index.data(Qt::DecorationRole).isNull()
                || !index.data(Qt::CheckStateRole).isNull())
                room -= view->iconSize().isValid() ? view->iconSize().width() + 4 : 20;
            if (fm.horizontalAdvance(text) <= room)
                continue;
            const QString tip = index.data(Qt::ToolTipRole).toString();
            if (!tip.contains(text, Qt::CaseInsensitive))
                out << QStringLiteral("%1: cell %2,%3 \"%4\" is %5 px in %6 px, no tooltip with it")
                           .arg(view->objectName())
                           .arg(r)
                           .arg(model->headerData(c, Qt::Horizontal).toString())
                           .arg(text)
                           .arg(fm.horizontalAdvance(text))
                           .arg(room);
        }
    }
    return out;
}

// Every text of `top` (its own window) a person cannot read whole.
QStringList cutTexts(QWidget *top)
{
    QStringList out;
    if (qobject_cast<QDialog *>(top) || top->isWindow()) {
        const QString title = top->windowTitle();
        const int titleWidth = top->fontMetrics().horizontalAdvance(title) + titleBarExtras;
        if (qobject_cast<QDialog *>(top) && titleWidth > top->width())
            out << QStringLiteral("title \"%1\" needs %2 px, the window is %3 px")
                       .arg(title)
                       .arg(titleWidth)
                       .arg(top->width());
    }
    for (QWidget *w : top->findChildren<QWidget *>()) {
        if (!w->isVisible() || w->window() != top || behindATab(w))
            continue;
        const QFontMetrics fm = w->fontMetrics();
        if (auto *label = qobject_cast<QLabel *>(w)) {
            const QString text = plainText(label->text()).remove(QLatin1Char('&'));
            if (text.isEmpty() || label->pixmap().isNull() == false)
                continue;
            const QRect room = label->contentsRect().adjusted(label->margin(), label->margin(),
                                                              -label->margin(), -label->margin());
            if (label->wordWrap()) {
                const int needed = label->heightForWidth(label->width());
                if (needed > label->height())
                    out << QStringLiteral("%1 wraps to %2 px, it is %3 px tall")
                               .arg(nameOf(label, text))
                               .arg(needed)
                               .arg(label->height());
            } else if (widestLine(fm, text) > room.width()) {
                out << QStringLiteral("%1 is %2 px in %3 px")
                           .arg(nameOf(label, text))
                           .arg(widestLine(fm, text))
                           .arg(room.width());
            }
        } else if (auto *button = qobject_cast<QAbstractButton *>(w)) {
            const auto *tool = qobject_cast<QToolButton *>(w);
            if (button->text().isEmpty()
                || (tool && tool->toolButtonStyle() == Qt::ToolButtonIconOnly)
                || qobject_cast<QAbstractItemView *>(w->parentWidget()))
                continue;
            if (button->width() < button->sizeHint().width())
                out << QStringLiteral("%1 is %2 px, its text needs %3 px")
                           .arg(nameOf(button, button->text()))
                           .arg(button->width())
                           .arg(button->sizeHint().width());
        } else if (auto *box = qobject_cast<QGroupBox *>(w)) {
            if (!box->title().isEmpty() && fm.horizontalAdvance(box->title()) + 16 > box->width())
                out << QStringLiteral("%1 is %2 px wide")
                           .arg(nameOf(box, box->title()))
                           .arg(box->width());
        } else if (auto *combo = qobject_cast<QComboBox *>(w)) {
            if (combo->isEditable() || combo->currentText().isEmpty())
                continue;
            QStyleOptionComboBox option;
            option.initFrom(combo);
            option.currentText = combo->currentText();
            const QRect field = combo->style()->subControlRect(QStyle::CC_ComboBox, &option,
                                                               QStyle::SC_ComboBoxEditField, combo);
            int room = field.width() - 4;
            if (!combo->itemIcon(combo->currentIndex()).isNull())
                room -= combo->iconSize().width() + 4;
            if (fm.horizontalAdvance(combo->currentText()) > room
                && !combo->toolTip().contains(combo->currentText()))
                out << QStringLiteral("%1 shows %2 px of %3 px")
                           .arg(nameOf(combo, combo->currentText()))
                           .arg(room)
                           .arg(fm.horizontalAdvance(combo->currentText()));
        } else if (auto *line = qobject_cast<MessageLine *>(w)) {
            // A message wraps: the tables' one-line message (whole in the status bar) aside.
            const QString shown = line->shownLines().join(QLatin1Char(' '));
            if (line->objectName() != QLatin1String("messageLabel") && !line->text().isEmpty()
                && shown.simplified() != line->text().simplified())
                out << QStringLiteral("%1 shows \"%2\"").arg(nameOf(line, line->text()), shown);
        } else if (auto *view = qobject_cast<QTableView *>(w)) {
            out << cutCells(view);
        } else if (auto *bar = qobject_cast<QStatusBar *>(w)) {
            const QString message = bar->currentMessage();
            int right = bar->width() - 12;
            for (QWidget *permanent : bar->findChildren<QWidget *>(Qt::FindDirectChildrenOnly)) {
                if (permanent->isVisible() && permanent->x() > bar->width() / 3)
                    right = std::min(right, permanent->x() - 2);
            }
            if (fm.horizontalAdvance(message) > right - 6)
                out << QStringLiteral("status bar message \"%1\" is %2 px, %3 px left of the "
                                      "link summary")
                           .arg(message)
                           .arg(fm.horizontalAdvance(message))
                           .arg(right - 6);
        }
    }
    return out;
}

} // namespace

class TestUiTextFit : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;
    std::unique_ptr<MainWindow> m_window;

    bool openDemo() { return UiTestUtil::openDemoWindow(m_window, true, longWait); }

    // Forcing's forced-points scan, clicked as a person would (its tab chosen first when the
    // dock shows tabs); true once its outcome is shown.
    static bool scanForcedPoints(QWidget *forcing)
    {
        auto *scan = forcing->findChild<QAbstractButton *>(QStringLiteral("scanButton"));
        if (!scan)
            return false;
        if (!scan->isVisible()) {
            auto *tabs = forcing->findChild<QTabWidget *>();
            if (!tabs)
                return false;
            tabs->setCurrentIndex(1);
        }
        if (!QTest::qWaitFor([scan] { return scan->isVisible(); }, 5000))
            return false;
        scan->click();
        auto *message = forcing->findChild<MessageLine *>(QStringLiteral("forcedMessage"));
        if (!message
            || !QTest::qWaitFor([message] { return !message->text().isEmpty(); }, longWait))
            return false;
        QTest::qWait(200);
        return true;
    }

    static QString report(const QStringList &problems)
    {
        return QStringLiteral("\n  ") + problems.join(QStringLiteral("\n  "));
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_textfit"));
        qInfo("screen %dx%d, scale %s",
              QGuiApplication::primaryScreen()->availableGeometry().width(),
              QGuiApplication::primaryScreen()->availableGeometry().height(),
              qgetenv("QT_SCALE_FACTOR").constData());
    }

    void cleanup()
    {
        m_window.reset();
        QSettings().clear();
    }

    // The window itself: the table, its connection box, the status bar with a message beside
    // the link summary.
    void mainWindowTextsFit()
    {
        QVERIFY(openDemo());
        QTest::qWait(1500); // ages, rates, a first status message
        // A message as long as the table's outcomes get.
        m_window->currentWatchTable()->addFromText(
            QStringLiteral("R100, R101, R102, R103, R104, R105, R106, R107, R108, R109"));
        QTest::qWait(200);
        const QStringList problems = cutTexts(m_window.get());
        QVERIFY2(problems.isEmpty(), qPrintable(report(problems)));
    }

    // A station that never answers: the Quality column says "no answer" whole, or in its
    // tooltip.
    void silentStationFits()
    {
        QVERIFY(openDemo());
        auto *model = m_window->currentWatchTable()->model();
        QVERIFY(model->setData(model->index(0, WatchTableModel::StationColumn), 7));
        QTRY_VERIFY_WITH_TIMEOUT(model->index(0, WatchTableModel::QualityColumn)
                                     .data()
                                     .toString()
                                     .startsWith(QStringLiteral("no answer")),
                                 longWait);
        const QStringList problems = cutTexts(m_window.get());
        QVERIFY2(problems.isEmpty(), qPrintable(report(problems)));
    }

    // Every dock and dialog the window offers.
    void everyToolFits_data()
    {
        QTest::addColumn<QString>("tool");
        for (const char *tool : {"control", "forcing", "console", "trend", "loopback", "program",
                                 "snapshot", "checkout"})
            QTest::newRow(tool) << QString::fromLatin1(tool);
    }
    void everyToolFits()
    {
        QFETCH(QString, tool);
        QVERIFY(openDemo());
        QWidget *opened = m_window->openTool(tool);
        QVERIFY(opened);
        QWidget *top = opened->window();
        QVERIFY(QTest::qWaitForWindowExposed(top));
        QTest::qWait(1500); // first answers, messages
        QStringList problems = cutTexts(top);
        if (tool == QLatin1String("forcing")) {
            // Its forced points: the scan's outcome and the list.
            QVERIFY(scanForcedPoints(opened));
            problems << cutTexts(top);
        }
        if (auto *checkout = qobject_cast<IoCheckoutDialog *>(top)) {
            // Its punch list and its report's details, each in its own window.
            checkout->showPunchList();
            QWidget *punch = checkout->punchDialog();
            QVERIFY(punch && QTest::qWaitForWindowExposed(punch));
            problems << cutTexts(punch);
            CheckoutDetailsDialog details(CheckoutInfo{}, checkout);
            details.show();
            QVERIFY(QTest::qWaitForWindowExposed(&details));
            problems << cutTexts(&details);
        }
        if (top != m_window.get())
            problems << cutTexts(m_window.get());
        problems.removeDuplicates();
        QVERIFY2(problems.isEmpty(), qPrintable(report(problems)));
    }

    // The connection dialog, each of its pages.
    // An M-series PLC over TCP on a five-digit port, as the issue met it: the table's connection
    // box names "127.0.0.1:NNNNN" whole, and PLC Control and Forcing (whose scan the M series
    // answers its own way) fit with this PLC's words.
    void mSeriesOverTcpFits()
    {
        SimulatedPlc plc(ModelProfile::mSeries());
        plc.setRunning(true);
        SimServer server(&plc);
        QVERIFY(server.listenTcp(0));
        m_window = std::make_unique<MainWindow>();
        m_window->setConfirmHandler([](QWidget *, const QString &) { return true; });
        m_window->showMaximized();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        SavedConnection saved;
        saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.tcpPort());
        Connection *c = m_window->openConnection(saved, false);
        QVERIFY(c);
        QTRY_VERIFY_WITH_TIMEOUT(c->plcText().contains(QStringLiteral("RUN")), longWait);
        m_window->currentWatchTable()->addFromText(QStringLiteral("R0, R1, Y0"));
        QStringList problems = cutTexts(m_window.get());
        for (const char *tool : {"control", "forcing"}) {
            QWidget *opened = m_window->openTool(QString::fromLatin1(tool));
            QVERIFY(opened);
            QTest::qWait(1500); // first answers, messages
            if (QLatin1String(tool) == QLatin1String("forcing"))
                QVERIFY(scanForcedPoints(opened));
            problems << cutTexts(opened->window());
        }
        problems.removeDuplicates();
        QVERIFY2(problems.isEmpty(), qPrintable(report(problems)));
        m_window.reset();
    }

    void connectionDialogFits()
    {
        QVERIFY(openDemo());
        auto *dialog = qobject_cast<QDialog *>(m_window->openTool(QStringLiteral("connection")));
        QVERIFY(dialog);
        QVERIFY(QTest::qWaitForWindowExposed(dialog));
        auto *kind = dialog->findChild<QComboBox *>(QStringLiteral("linkKindCombo"));
        QVERIFY(kind);
        QStringList problems;
        for (int i = 0; i < kind->count(); ++i) {
            kind->setCurrentIndex(i);
            QTest::qWait(100);
            problems << cutTexts(dialog);
        }
        dialog->reject();
        problems.removeDuplicates();
        QVERIFY2(problems.isEmpty(), qPrintable(report(problems)));
    }

    // A question before a change: its title is whole in the title bar.
    void confirmationTitleFits()
    {
        QVERIFY(openDemo());
        QStringList problems;
        UiTestUtil::answerModal(
            [this] {
                ToolConfirmation::ask(m_window.get(), QStringLiteral("Enable all forced points"),
                                      QStringLiteral("Enable 3 points?"), {});
            },
            [&problems](QWidget *box) {
                problems << cutTexts(box);
                if (auto *question = qobject_cast<QMessageBox *>(box))
                    question->reject();
            });
        QVERIFY2(problems.isEmpty(), qPrintable(report(problems)));
    }

    // The raw console in an 800 px wide window: it fits.
    void consoleFitsANarrowWindow()
    {
        QVERIFY(openDemo());
        m_window->showNormal();
        m_window->resize(800, 560);
        QTRY_COMPARE(m_window->width(), 800);
        QWidget *console = m_window->openTool(QStringLiteral("console"));
        QVERIFY(console);
        auto *dock = m_window->findChild<QDockWidget *>(QStringLiteral("rawConsoleDock"));
        QVERIFY(dock);
        QTest::qWait(300);
        QVERIFY2(m_window->width() <= 800 && dock->width() <= 800,
                 qPrintable(QStringLiteral("window %1 px, console dock %2 px")
                                .arg(m_window->width())
                                .arg(dock->width())));
        const QStringList problems = cutTexts(m_window.get());
        QVERIFY2(problems.isEmpty(), qPrintable(report(problems)));
    }
};

// A laptop's screen (1366x768), or with --small a 1280x720 one (run with QT_SCALE_FACTOR=1.25).
int main(int argc, char *argv[])
{
    QList<char *> args;
    for (int i = 0; i < argc; ++i) {
        if (qstrcmp(argv[i], "--small") == 0)
            smallScreen = true;
        else
            args << argv[i];
    }
    const UiTestUtil::OffscreenScreen screen(smallScreen ? QSize(1280, 720) : QSize(1366, 768));
    if (!screen.isReady())
        return 1;
    int count = static_cast<int>(args.size());
    QApplication app(count, args.data());
    TestUiTextFit test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, count, args.data());
}

#include "tst_ui_textfit.moc"
