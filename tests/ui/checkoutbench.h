// The I/O checkout's bench for the UI tests (tst_ui_checkout, tst_ui_checkoutplan): a simulated
// FBs over loopback TCP (STOP, no demo ladder: only the test moves the inputs, as the
// technician's hand in the field), the real main window at a laptop's size connected to it, the
// tool opened from the Tools menu with the mouse, and a person's hands on its table.
#pragma once

#include "core/commission/checkoutrunner.h"
#include "core/commission/commissionmessages.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "ui/common/uitext.h"
#include "ui/connection/connection.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/tools/checkouttablemodel.h"
#include "ui/tools/iocheckoutdialog.h"

#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <memory>

namespace CheckoutBench {

inline constexpr QSize laptop(1366, 768);
inline constexpr int longWait = 30000;
inline constexpr int keyDelayMs = 20;

inline Fatek::Address addr(const char *text)
{
    return *Fatek::Address::parse(text);
}

// Answers a force question with its Yes button, as a person would.
inline void clickYes(QWidget *modal)
{
    auto *box = qobject_cast<QMessageBox *>(modal);
    if (!box || !box->button(QMessageBox::Yes)) {
        qWarning("not a yes/no question");
        return;
    }
    QTest::mouseClick(box->button(QMessageBox::Yes), Qt::LeftButton);
}

inline QString resultText(Fatek::CheckoutResult result)
{
    return Fatek::translated(Fatek::checkoutResultMessage(result));
}

inline QString state(const Fatek::IoCheckoutDialog *dialog, int row)
{
    return dialog->points()->index(row, Fatek::CheckoutTableModel::StateColumn).data().toString();
}

// Clicks `button` and, in the menu it opens, the entry `actionName`, as a person does (the menu
// runs its own event loop: the entry is clicked from a timer). False when the entry is not there.
inline bool pickFromMenu(QPushButton *button, const char *actionName)
{
    QMenu *menu = button ? button->menu() : nullptr;
    QAction *action = menu ? menu->findChild<QAction *>(QLatin1String(actionName)) : nullptr;
    if (!action)
        return false;
    bool picked = false;
    QTimer timer;
    timer.setInterval(50);
    QObject::connect(&timer, &QTimer::timeout, menu, [&] {
        if (!menu->isVisible())
            return;
        timer.stop();
        QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(action).center());
        picked = true;
    });
    timer.start();
    QTest::mouseClick(button, Qt::LeftButton);
    return QTest::qWaitFor([&picked] { return picked; }, longWait);
}

// Every question the dialog asks is answered yes and kept in `questions`.
inline void answerYes(Fatek::IoCheckoutDialog *dialog, QStringList &questions)
{
    dialog->setConfirmer([&questions](const QString &question) {
        questions << question;
        return true;
    });
}

struct Bench
{
    QTemporaryDir files;
    std::unique_ptr<Fatek::SimulatedPlc> plc;
    std::unique_ptr<Fatek::SimServer> server;
    std::unique_ptr<Fatek::MainWindow> window;

    // A stopped FBs listening on a free port; false (and `error`) when it cannot listen.
    bool init(QString *error)
    {
        plc = std::make_unique<Fatek::SimulatedPlc>(Fatek::ModelProfile::fbs());
        plc->setRunning(false);
        server = std::make_unique<Fatek::SimServer>(plc.get());
        return server->listenTcp(0, error);
    }

    void cleanup()
    {
        window.reset();
        server.reset();
        plc.reset();
    }

    // The main window at the laptop's size, connected to the simulator.
    bool openWindow(bool operatorMode)
    {
        window = std::make_unique<Fatek::MainWindow>(operatorMode);
        window->resize(laptop - QSize(0, 70));
        window->show();
        if (!QTest::qWaitForWindowExposed(window.get()))
            return false;
        Fatek::SavedConnection saved;
        saved.name = QStringLiteral("Line 3");
        saved.settings = Fatek::LinkSettings::tcp(QStringLiteral("127.0.0.1"), server->tcpPort());
        saved.settings.protocol = Fatek::LinkSettings::ProtocolChoice::Facon;
        saved.settings.timeoutMs = 2000;
        saved.settings.retries = 1;
        Fatek::Connection *c = window->openConnection(saved, false);
        return c
               && QTest::qWaitFor([c] { return c->linkState() == Fatek::LinkState::Connected; },
                                  longWait);
    }

    // Opens Tools -> I/O Checkout with the mouse.
    Fatek::IoCheckoutDialog *openFromToolsMenu()
    {
        QMenuBar *bar = window->menuBar();
        QAction *entry = window->findChild<QAction *>(QStringLiteral("ioCheckoutAction"));
        QAction *tools = nullptr;
        for (QAction *a : bar->actions()) {
            if (a->menu() && a->menu()->actions().contains(entry))
                tools = a;
        }
        if (!tools)
            return nullptr;
        QTest::mouseClick(bar, Qt::LeftButton, {}, bar->actionGeometry(tools).center());
        QMenu *menu = tools->menu();
        if (!QTest::qWaitFor([menu] { return menu->isVisible(); }, longWait))
            return nullptr;
        QTest::qWait(200);
        QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(entry).center());
        Fatek::IoCheckoutDialog *dialog = nullptr;
        const bool shown = QTest::qWaitFor(
            [&] {
                dialog = window->findChild<Fatek::IoCheckoutDialog *>(
                    QStringLiteral("ioCheckoutDialog"));
                return dialog && dialog->isVisible();
            },
            longWait);
        return shown ? dialog : nullptr;
    }

    // The plan `ranges` typed and Start pressed, saved in `fileName`; false when the fields are
    // not there.
    bool startPlan(Fatek::IoCheckoutDialog *dialog, const QString &ranges, const QString &fileName)
    {
        const QString file = files.filePath(fileName);
        dialog->setFileChooser(
            [file](const Fatek::ToolDialogFrame::FileQuestion &) { return file; });
        auto *edit = dialog->findChild<QLineEdit *>(QStringLiteral("ranges"));
        auto *start = dialog->findChild<QPushButton *>(QStringLiteral("startButton"));
        if (!edit || !start)
            return false;
        QTest::mouseClick(edit, Qt::LeftButton);
        QTest::keyClicks(edit, ranges, {}, keyDelayMs);
        QTest::mouseClick(start, Qt::LeftButton);
        return true;
    }

    // The technician presses the switch and lets it go, each state held until the tool saw it;
    // true once the point has both edges (passed, or failed for crossed wiring).
    bool actuate(Fatek::IoCheckoutDialog *dialog, const char *input)
    {
        const int i = dialog->runner()->plan().indexOf(addr(input));
        if (i < 0)
            return false;
        const auto point = [dialog, i]() -> const Fatek::CheckoutPoint & {
            return dialog->runner()->plan().points[static_cast<std::size_t>(i)];
        };
        // Its first poll shown: 0 is the baseline the change is seen against.
        if (!QTest::qWaitFor(
                [dialog, i] {
                    return dialog->points()
                        ->index(i, Fatek::CheckoutTableModel::MeasuredColumn)
                        .data()
                        .toString()
                        .endsWith(Fatek::CheckoutTableModel::tr("now %1").arg(0));
                },
                longWait))
            return false;
        plc->setValue(addr(input), 1);
        if (!QTest::qWaitFor([&] { return point().rose.isValid(); }, longWait))
            return false;
        plc->setValue(addr(input), 0);
        return QTest::qWaitFor([&] { return point().result != Fatek::CheckoutResult::Untested; },
                               longWait);
    }
};

} // namespace CheckoutBench
