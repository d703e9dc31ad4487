#include "tooldocks.h"

#include "mainwindow.h"
#include "toolscrollarea.h"
#include "ui/connection/connection.h"
#include "ui/connection/stationscandialog.h"
#include "ui/tools/forcingpanel.h"
#include "ui/tools/iocheckoutdialog.h"
#include "ui/tools/loopbackdialog.h"
#include "ui/tools/plccontrolpanel.h"
#include "ui/tools/programtransferdialog.h"
#include "ui/tools/rawconsole.h"
#include "ui/tools/snapshotdialog.h"

#include <QAction>
#include <QDialog>
#include <QDockWidget>
#include <QHash>
#include <QMenu>
#include <QScrollArea>

#include <algorithm>

namespace Fatek {

namespace {

// What the tools act on: the connection's station behind its link (none without a connection).
PlcTarget targetOf(const Connection *c)
{
    return c ? PlcTarget(c->link(), c->station(), c->name()) : PlcTarget();
}

} // namespace

ToolDocks::ToolDocks(MainWindow *window, QDockWidget *tabWith, QMenu *toolsMenu, QMenu *viewMenu)
    : QObject(window)
    , m_window(window)
{
    auto addDock = [this, window, toolsMenu, viewMenu](auto *tool, const QString &title,
                                                       const QString &name, Qt::DockWidgetArea area,
                                                       const QKeySequence &shortcut) {
        auto *dock = new QDockWidget(title, window);
        dock->setObjectName(name);
        // In a scroll area a tool's own minimum height (rows of controls, long status lines) no
        // longer sets the window's: with every tool open it still fits 1366x768, or 1920x1080
        // at 150 %. Its width is kept whole: nothing needs a sideways scroll.
        auto *scroll = new ToolScrollArea(tool, dock);
        scroll->setObjectName(name + QStringLiteral("Scroll"));
        dock->setWidget(scroll);
        // A side dock opens as wide as its tool needs (its buttons at the side reachable),
        // however it is opened; it does not widen later on its own.
        connect(dock, &QDockWidget::visibilityChanged, this, [window, dock, scroll](bool shown) {
            // Hidden: nothing to do, and the window may be closing down (its layout half gone:
            // dockWidgetArea() would crash, as tst_ui_mainwindow saw under ctest -j2).
            if (!shown || !window->isVisible())
                return;
            const Qt::DockWidgetArea side = window->dockWidgetArea(dock);
            if (!dock->isFloating()
                && (side == Qt::LeftDockWidgetArea || side == Qt::RightDockWidgetArea)
                && scroll->viewport()->width() < scroll->wholeWidth())
                window->resizeDocks(
                    {dock}, {dock->width() - scroll->viewport()->width() + scroll->wholeWidth()},
                    Qt::Horizontal);
            // A bottom dock opens tall enough for its tool, up to 45 % of the window: at 800 px
            // the raw console showed one row of traffic under its controls.
            const int wanted = std::min(scroll->usefulHeight(), window->height() * 45 / 100);
            if (!dock->isFloating()
                && (side == Qt::BottomDockWidgetArea || side == Qt::TopDockWidgetArea)
                && scroll->viewport()->height() < wanted)
                window->resizeDocks(
                    {dock}, {dock->height() - scroll->viewport()->height() + wanted}, Qt::Vertical);
        });
        window->addDockWidget(area, dock);
        QAction *action = dockAction(dock, shortcut, window);
        toolsMenu->addAction(action);
        viewMenu->addAction(action);
        m_targets.append([tool](const PlcTarget &target) { tool->setTarget(target); });
        m_docks.append(dock);
        m_titles.append(title);
        return dock;
    };
    QDockWidget *control
        = addDock(new PlcControlPanel(window), tr("PLC Control"), QStringLiteral("plcControlDock"),
                  Qt::RightDockWidgetArea, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    QDockWidget *forcing
        = addDock(new ForcingPanel(window), tr("Forcing"), QStringLiteral("forcingDock"),
                  Qt::RightDockWidgetArea, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    auto *rawConsole = new RawConsole(window);
    QDockWidget *console
        = addDock(rawConsole, tr("Raw Console"), QStringLiteral("rawConsoleDock"),
                  Qt::BottomDockWidgetArea, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    // A dock behind another tab is not hidden, only covered: its tab tells the console.
    connect(console, &QDockWidget::visibilityChanged, rawConsole, &RawConsole::setOnScreen);
    window->tabifyDockWidget(control, forcing);
    // The watch tables own the width: the side tools start hidden (Tools menu, shortcuts above);
    // the console shares the bottom area with the connections as a tab. QSettings keeps what the
    // user arranges after that.
    control->hide();
    forcing->hide();
    window->tabifyDockWidget(tabWith, console);
    tabWith->raise();
    // The menus tick the docks that are open. A dock hidden before the window is shown (above,
    // or by a restored layout) sends no hide event, so its toggle action stays ticked: the ticks
    // are read from the docks themselves whenever a menu opens (they showed PLC Control and
    // Forcing ticked at the first start, neither on screen).
    const auto tickOpenDocks = [window] {
        for (QDockWidget *dock : window->findChildren<QDockWidget *>()) {
            dock->toggleViewAction()->setChecked(!dock->isHidden()); // the trend's entry
            if (auto *action
                = window->findChild<QAction *>(dock->objectName() + QStringLiteral("Action")))
                action->setChecked(!dock->isHidden());
        }
    };
    tickOpenDocks();
    connect(toolsMenu, &QMenu::aboutToShow, this, tickOpenDocks);
    connect(viewMenu, &QMenu::aboutToShow, this, tickOpenDocks);
    toolsMenu->addSeparator();
    m_loopbackAction = toolsMenu->addAction(tr("&Loopback Test…"), this, [this] {
        openDialog(new LoopbackDialog(m_window), QStringLiteral("loopbackDialog"));
    });
    m_loopbackAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L));
    auto *program = toolsMenu->addAction(tr("&Program Backup / Restore…"), this, [this] {
        // One dialog at a time: a second one would run a second transfer on the same PLC.
        if (auto *open = m_window->findChild<ProgramTransferDialog *>(
                QStringLiteral("programTransferDialog"))) {
            open->raise();
            open->activateWindow();
            return;
        }
        openDialog(new ProgramTransferDialog(m_window), QStringLiteral("programTransferDialog"));
    });
    program->setObjectName(QStringLiteral("programTransferAction"));
    program->setToolTip(tr("Save the PLC's program in a file, or write a saved one back"));
    auto *snapshot = toolsMenu->addAction(tr("Memory S&napshot…"), this, [this] {
        openDialog(new SnapshotDialog(m_window), QStringLiteral("snapshotDialog"));
    });
    snapshot->setObjectName(QStringLiteral("memorySnapshotAction"));
    snapshot->setToolTip(tr("Save, compare and restore element values of the current station"));
    auto *checkout = toolsMenu->addAction(tr("I/O &Checkout…"), this, [this] {
        // One checkout at a time: two would force outputs of the same machine.
        if (auto *open
            = m_window->findChild<IoCheckoutDialog *>(QStringLiteral("ioCheckoutDialog"))) {
            open->raise();
            open->activateWindow();
            return;
        }
        auto *dialog = new IoCheckoutDialog(m_window);
        // Typed ranges get the project's names, and a plan is made from them.
        dialog->setSymbols(m_window->symbolNames());
        openDialog(dialog, QStringLiteral("ioCheckoutDialog"));
    });
    checkout->setObjectName(QStringLiteral("ioCheckoutAction"));
    checkout->setToolTip(
        tr("Check every input, output and analog point of a machine and write the report"));
    auto *scan = toolsMenu->addAction(tr("Scan &Stations…"), this, [this] {
        Connection *c = m_connection;
        if (!c) {
            Q_EMIT statusMessage(tr("Scan Stations: open a connection first."));
            return;
        }
        auto *dialog = new StationScanDialog(targetOf(c), m_window);
        connect(dialog, &StationScanDialog::stationChosen, c, &Connection::setStation);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->show();
        dialog->start();
    });
    scan->setObjectName(QStringLiteral("scanStationsAction"));
    scan->setToolTip(tr("Find the PLCs that answer on the current connection's link"));
    for (QAction *action : {m_loopbackAction, program, snapshot, checkout, scan})
        m_linkActions.insert(action, action->toolTip());
    setTarget(window->toolConnection());
}

template<typename Dialog>
void ToolDocks::openDialog(Dialog *dialog, const QString &objectName)
{
    dialog->setObjectName(objectName);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setTarget(targetOf(m_connection));
    // Like the docks, an open dialog follows the current connection (and lets go of a closed
    // one).
    m_targets.append([open = QPointer<Dialog>(dialog)](const PlcTarget &target) {
        if (open)
            open->setTarget(target);
    });
    dialog->show();
}

QAction *ToolDocks::dockAction(QDockWidget *dock, const QKeySequence &shortcut, QObject *parent)
{
    // The dock's own toggle action hides a dock that is open but behind another tab: this one
    // brings it to the front first, and hides it only when it is already in front.
    auto *action = new QAction(dock->windowTitle(), parent);
    action->setObjectName(dock->objectName() + QStringLiteral("Action"));
    action->setCheckable(true);
    action->setChecked(!dock->isHidden());
    action->setShortcut(shortcut);
    connect(dock->toggleViewAction(), &QAction::toggled, action, &QAction::setChecked);
    connect(action, &QAction::triggered, dock, [dock, action] {
        if (dock->isHidden()) {
            dock->show();
            dock->raise();
        } else if (!dock->isVisible() || dock->visibleRegion().isEmpty()) {
            dock->raise(); // open, but another tab is in front
        } else {
            dock->hide();
        }
        action->setChecked(!dock->isHidden());
    });
    return action;
}

QWidget *ToolDocks::openTool(const QString &name)
{
    static const QHash<QString, QString> docks
        = {{QStringLiteral("control"), QStringLiteral("plcControlDock")},
           {QStringLiteral("forcing"), QStringLiteral("forcingDock")},
           {QStringLiteral("console"), QStringLiteral("rawConsoleDock")}};
    if (docks.contains(name)) {
        auto *dock = m_window->findChild<QDockWidget *>(docks.value(name));
        if (!dock)
            return nullptr;
        dock->show();
        dock->raise();
        auto *scroll = qobject_cast<QScrollArea *>(dock->widget());
        return scroll ? scroll->widget() : dock->widget();
    }
    if (name == QLatin1String("loopback")) {
        m_loopbackAction->trigger();
        auto *dialog = m_window->findChild<LoopbackDialog *>(QStringLiteral("loopbackDialog"));
        if (dialog)
            dialog->start();
        return dialog;
    }
    // The dialogs, opened through their Tools actions as a person opens them: action, dialog.
    static const QHash<QString, std::pair<QString, QString>> dialogs
        = {{QStringLiteral("program"),
            {QStringLiteral("programTransferAction"), QStringLiteral("programTransferDialog")}},
           {QStringLiteral("snapshot"),
            {QStringLiteral("memorySnapshotAction"), QStringLiteral("snapshotDialog")}},
           {QStringLiteral("checkout"),
            {QStringLiteral("ioCheckoutAction"), QStringLiteral("ioCheckoutDialog")}}};
    if (dialogs.contains(name)) {
        const auto &[actionName, dialogName] = dialogs.value(name);
        auto *action = m_window->findChild<QAction *>(actionName);
        if (!action)
            return nullptr;
        action->trigger();
        return m_window->findChild<QDialog *>(dialogName);
    }
    return nullptr;
}

void ToolDocks::setTarget(Connection *c, bool force)
{
    const quint8 station = c ? c->station() : quint8(1);
    if (!force && c == m_connection && station == m_station)
        return;
    m_connection = c;
    m_station = station;
    for (const SetTarget &target : std::as_const(m_targets))
        target(targetOf(c));
    // The dock's title names the PLC its buttons act on (RUN/STOP, forcing, raw frames), also
    // when the dock floats or sits behind another tab.
    for (qsizetype i = 0; i < m_docks.size(); ++i)
        m_docks.at(i)->setWindowTitle(
            c ? tr("%1 \u2014 %2, station %3").arg(m_titles.at(i), c->name()).arg(station)
              : m_titles.at(i));
    showGatewayNotice(c && c->isGateway());
}

QString ToolDocks::gatewayNotice()
{
    return tr("Not available through an MQTT gateway connection: this tool needs a direct link "
              "to the PLC.");
}

void ToolDocks::showGatewayNotice(bool gateway)
{
    // The tools need the PLC's own link (forcing, RUN/STOP, raw frames, loopback, program,
    // snapshots, station scan): greyed out with the reason, never pointed at a gateway.
    const QString notice = gateway ? gatewayNotice() : QString();
    for (QDockWidget *dock : std::as_const(m_docks)) {
        dock->widget()->setEnabled(!gateway);
        dock->widget()->setToolTip(notice);
        if (gateway && dock->isVisible())
            Q_EMIT statusMessage(tr("%1: %2").arg(dock->windowTitle(), notice));
    }
    for (auto it = m_linkActions.cbegin(); it != m_linkActions.cend(); ++it) {
        it.key()->setEnabled(!gateway);
        it.key()->setToolTip(gateway ? notice : it.value());
        it.key()->setStatusTip(notice);
    }
}

void ToolDocks::releaseTargets()
{
    for (const SetTarget &target : std::as_const(m_targets))
        target(PlcTarget());
}

} // namespace Fatek
