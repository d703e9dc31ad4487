#include "mainwindow.h"

#include "connectiondialog.h"
#include "connectionmanager.h"
#include "connectionspanel.h"
#include "coretext.h"
#include "demosimulator.h"
#include "forcingpanel.h"
#include "languagemenu.h"
#include "loopbackdialog.h"
#include "plccontrolpanel.h"
#include "rawconsole.h"
#include "stationscandialog.h"
#include "tablelogger.h"
#include "trendview.h"
#include "watchtablemodel.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHash>
#include <QInputDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTableView>
#include <QToolBar>

#include <algorithm>
#include <memory>

// Q_INIT_RESOURCE must be called from the global namespace.
static void initStudioResources()
{
    Q_INIT_RESOURCE(studio);
}

namespace Fatek {

namespace {
const QString geometryKey = QStringLiteral("mainwindow/geometry");
const QString stateKey = QStringLiteral("mainwindow/state");
const QString directoryKey = QStringLiteral("preferences/lastDirectory");
const QString lastListKey = QStringLiteral("preferences/lastWatchList");
const QString reopenKey = QStringLiteral("preferences/reopenLastWatchList");
} // namespace

MainWindow::MainWindow(bool readOnly, QWidget *parent)
    : QMainWindow(parent)
    , m_readOnly(readOnly)
    , m_manager(new ConnectionManager(this))
{
    initStudioResources();
    setObjectName(QStringLiteral("mainWindow"));
    setWindowIcon(QIcon(QStringLiteral(":/icons/fatek-studio.svg")));
    m_manager->setReadOnly(readOnly);

    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("watchTabs"));
    m_tabs->setTabsClosable(true);
    m_tabs->setMovable(true);
    m_tabs->setDocumentMode(true);
    setCentralWidget(m_tabs);
    connect(m_tabs, &QTabWidget::tabCloseRequested, this, &MainWindow::closeWatchTable);
    // The tools act on the table in front: its connection becomes the current one.
    connect(m_tabs, &QTabWidget::currentChanged, this, [this] {
        if (WatchTableWidget *t = currentWatchTable())
            followTable(t->connection());
    });
    connect(m_tabs->tabBar(), &QTabBar::tabBarDoubleClicked, this, &MainWindow::renameWatchTable);

    m_connectionsPanel = new ConnectionsPanel(m_manager, this);
    auto *connectionsDock = new QDockWidget(tr("Connections"), this);
    connectionsDock->setObjectName(QStringLiteral("connectionsDock"));
    connectionsDock->setWidget(m_connectionsPanel);
    addDockWidget(Qt::BottomDockWidgetArea, connectionsDock);

    m_linkStatus = new QLabel(tr("No connection"), this);
    m_linkStatus->setObjectName(QStringLiteral("linkStatus"));
    statusBar()->addPermanentWidget(m_linkStatus);
    updateModeLabel(readOnly);

    createActions();
    createTools();
    addWatchTable();
    markWatchListSaved({});

    connect(m_connectionsPanel, &ConnectionsPanel::currentConnectionChanged, this, [this] {
        updateLinkStatus();
        updateToolTargets();
    });
    connect(m_manager, &ConnectionManager::connectionChanged, this, [this](Connection *c) {
        if (c == currentConnection()) {
            updateLinkStatus();
            updateToolTargets(); // the station may have changed
        }
    });
    connect(m_manager, &ConnectionManager::recentChanged, this, &MainWindow::rebuildRecentMenu);
    connect(m_manager, &ConnectionManager::connectionAdded, this, [this](Connection *c) {
        connect(c, &Connection::linkStateChanged, this,
                [this, c](LinkState state, const QString &reason) {
                    showStatus(reason.isEmpty()
                                   ? tr("%1: %2").arg(c->name(), CoreText::linkState(state))
                                   : tr("%1: %2 (%3)")
                                         .arg(c->name(), CoreText::linkState(state),
                                              CoreText::message(reason)));
                });
    });

    resize(1280, 800);
    if (auto *dock = findChild<QDockWidget *>(QStringLiteral("connectionsDock")))
        resizeDocks({dock}, {150}, Qt::Vertical);
    QSettings settings;
    restoreGeometry(settings.value(geometryKey).toByteArray());
    restoreState(settings.value(stateKey).toByteArray());
}

MainWindow::~MainWindow()
{
    // Tear down in dependency order: tools and tables hold sessions, the connections panel reads
    // the manager, the manager owns the sessions.
    disconnect(m_connectionsPanel, nullptr, this, nullptr);
    disconnect(m_manager, nullptr, this, nullptr);
    disconnect(m_tabs, nullptr, this, nullptr);
    for (const auto &setTarget : std::as_const(m_toolTargets))
        setTarget(nullptr, 1, QString());
    while (m_tabs->count() > 0) {
        QWidget *w = m_tabs->widget(0);
        m_tabs->removeTab(0);
        delete w;
    }
    delete m_connectionsPanel;
    delete m_manager;
}

void MainWindow::createActions()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QToolBar *toolBar = addToolBar(tr("Main"));
    toolBar->setObjectName(QStringLiteral("mainToolBar"));
    toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);

    auto *connectAction
        = file->addAction(QIcon(QStringLiteral(":/icons/connect.svg")), tr("&New Connection…"),
                          this, &MainWindow::newConnectionDialog);
    connectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N));
    m_recentMenu = file->addMenu(tr("&Recent Connections"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    rebuildRecentMenu();
    auto *disconnectAction
        = file->addAction(QIcon(QStringLiteral(":/icons/disconnect.svg")), tr("&Close Connection"),
                          this, &MainWindow::closeCurrentConnection);
    disconnectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_W));
    m_reconnectAction = file->addAction(tr("&Reconnect Now"), this, [this] {
        if (Connection *c = currentConnection()) {
            showStatus(tr("Reconnecting %1 now…").arg(c->name()));
            c->reconnectNow();
        }
    });
    m_reconnectAction->setObjectName(QStringLiteral("reconnectNowAction"));
    m_reconnectAction->setShortcut(QKeySequence(Qt::Key_F5));
    m_reconnectAction->setToolTip(tr("Try the current connection again at once instead of "
                                     "waiting for the next attempt"));
    m_reconnectAction->setEnabled(false);
    file->addSeparator();
    auto *newTable
        = file->addAction(QIcon(QStringLiteral(":/icons/table.svg")), tr("New &Watch Table"), this,
                          [this] { m_tabs->setCurrentWidget(addWatchTable()); });
    newTable->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
    auto *openAction
        = file->addAction(QIcon(QStringLiteral(":/icons/open.svg")), tr("&Open Watch List…"), this,
                          &MainWindow::openWatchListDialog);
    openAction->setShortcut(QKeySequence::Open);
    auto *saveAction
        = file->addAction(QIcon(QStringLiteral(":/icons/save.svg")), tr("&Save Watch List…"), this,
                          &MainWindow::saveWatchListDialog);
    saveAction->setShortcut(QKeySequence::Save);
    auto *importAction = file->addAction(tr("&Import CSV…"), this, &MainWindow::importCsvDialog);
    importAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    auto *reopen = file->addAction(tr("Reopen Last Watch List at Start"));
    reopen->setCheckable(true);
    reopen->setChecked(QSettings().value(reopenKey, true).toBool());
    connect(reopen, &QAction::toggled, this, [](bool on) { QSettings().setValue(reopenKey, on); });
    file->addSeparator();
    auto *quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    // QKeySequence::Quit is empty on Windows and in some desktop themes.
    quit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));

    QMenu *watch = menuBar()->addMenu(tr("&Watch"));
    auto *focusAdd = watch->addAction(tr("&Add Items…"), this, [this] {
        if (WatchTableWidget *t = currentWatchTable())
            t->addressEdit()->setFocus();
    });
    focusAdd->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    auto *pause = watch->addAction(QIcon(QStringLiteral(":/icons/pause.svg")), tr("&Pause Table"),
                                   this, [this] {
                                       if (WatchTableWidget *t = currentWatchTable())
                                           t->setPaused(!t->isPaused());
                                   });
    pause->setShortcut(QKeySequence(Qt::Key_F8));
    auto *closeTable = watch->addAction(tr("&Close Table"), this,
                                        [this] { closeWatchTable(m_tabs->currentIndex()); });
    closeTable->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F4));

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        m_viewMenu->addAction(dock->toggleViewAction());
    m_viewMenu->addAction(toolBar->toggleViewAction());

    m_toolsMenu = menuBar()->addMenu(tr("&Tools"));
    createTrendAndLogging();
    createOperatorMode();
    m_viewMenu->addSeparator();
    m_viewMenu->addMenu(new LanguageMenu(m_viewMenu));

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About FATEK Studio"), this, [this] {
        QMessageBox::about(this, tr("About FATEK Studio"),
                           tr("FATEK Studio %1\nCommissioning and monitoring tool for FATEK PLCs.")
                               .arg(QApplication::applicationVersion()));
    });

    toolBar->addAction(connectAction);
    toolBar->addAction(disconnectAction);
    toolBar->addSeparator();
    toolBar->addAction(newTable);
    toolBar->addAction(openAction);
    toolBar->addAction(saveAction);
    toolBar->addAction(pause);
}

void MainWindow::createTools()
{
    auto addDock = [this](auto *tool, const QString &title, const QString &name,
                          Qt::DockWidgetArea area, const QKeySequence &shortcut) {
        auto *dock = new QDockWidget(title, this);
        dock->setObjectName(name);
        // In a scroll area a tool's own minimum (rows of controls, long status lines) no longer
        // sets the window's: with every tool open it still fits 1366x768, or 1920x1080 at 150 %.
        auto *scroll = new QScrollArea(dock);
        scroll->setObjectName(name + QStringLiteral("Scroll"));
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidget(tool);
        dock->setWidget(scroll);
        addDockWidget(area, dock);
        QAction *action = dockAction(dock, shortcut);
        m_toolsMenu->addAction(action);
        m_viewMenu->addAction(action);
        m_toolTargets.append([tool](Session *session, quint8 station, const QString &connection) {
            tool->setTarget(session, station, connection);
        });
        return dock;
    };
    QDockWidget *control
        = addDock(new PlcControlPanel(this), tr("PLC Control"), QStringLiteral("plcControlDock"),
                  Qt::RightDockWidgetArea, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    QDockWidget *forcing
        = addDock(new ForcingPanel(this), tr("Forcing"), QStringLiteral("forcingDock"),
                  Qt::RightDockWidgetArea, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    QDockWidget *console
        = addDock(new RawConsole(this), tr("Raw Console"), QStringLiteral("rawConsoleDock"),
                  Qt::BottomDockWidgetArea, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    tabifyDockWidget(control, forcing);
    // The watch tables own the width: the side tools start hidden (Tools menu, shortcuts above);
    // the console shares the bottom area with the connections as a tab. QSettings keeps what the
    // user arranges after that.
    control->hide();
    forcing->hide();
    if (auto *connectionsDock = findChild<QDockWidget *>(QStringLiteral("connectionsDock"))) {
        tabifyDockWidget(connectionsDock, console);
        connectionsDock->raise();
    }
    m_toolsMenu->addSeparator();
    auto *loopback = m_toolsMenu->addAction(tr("&Loopback Test…"), this, [this] {
        auto *dialog = new LoopbackDialog(this);
        dialog->setObjectName(QStringLiteral("loopbackDialog"));
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        Connection *c = currentConnection();
        dialog->setTarget(c ? c->session() : nullptr, c ? c->station() : quint8(1),
                          c ? c->name() : QString());
        // Like the docks, an open dialog follows the current connection (and lets go of a closed
        // one).
        m_toolTargets.append([target = QPointer<LoopbackDialog>(dialog)](
                                 Session *session, quint8 station, const QString &name) {
            if (target)
                target->setTarget(session, station, name);
        });
        dialog->show();
    });
    loopback->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L));
    auto *scan = m_toolsMenu->addAction(tr("Scan &Stations…"), this, [this] {
        Connection *c = currentConnection();
        if (!c) {
            showStatus(tr("Scan Stations: open a connection first."));
            return;
        }
        auto *dialog = new StationScanDialog(c, this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->show();
        dialog->start();
    });
    scan->setObjectName(QStringLiteral("scanStationsAction"));
    scan->setToolTip(tr("Find the PLCs that answer on the current connection's link"));
    updateToolTargets();
}

QAction *MainWindow::dockAction(QDockWidget *dock, const QKeySequence &shortcut)
{
    // The dock's own toggle action hides a dock that is open but behind another tab: this one
    // brings it to the front first, and hides it only when it is already in front.
    auto *action = new QAction(dock->windowTitle(), this);
    action->setObjectName(dock->objectName() + QStringLiteral("Action"));
    action->setCheckable(true);
    action->setChecked(!dock->isHidden());
    action->setShortcut(shortcut);
    connect(dock->toggleViewAction(), &QAction::toggled, action, &QAction::setChecked);
    connect(dock, &QDockWidget::windowTitleChanged, action, &QAction::setText);
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

QWidget *MainWindow::openTool(const QString &name)
{
    if (name == QLatin1String("trend"))
        return showTrend();
    static const QHash<QString, QString> docks
        = {{QStringLiteral("control"), QStringLiteral("plcControlDock")},
           {QStringLiteral("forcing"), QStringLiteral("forcingDock")},
           {QStringLiteral("console"), QStringLiteral("rawConsoleDock")}};
    if (docks.contains(name)) {
        auto *dock = findChild<QDockWidget *>(docks.value(name));
        if (!dock)
            return nullptr;
        dock->show();
        dock->raise();
        auto *scroll = qobject_cast<QScrollArea *>(dock->widget());
        return scroll ? scroll->widget() : dock->widget();
    }
    if (name == QLatin1String("loopback")) {
        for (QAction *action : m_toolsMenu->actions()) {
            if (action->shortcut() == QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L))
                action->trigger();
        }
        auto *dialog = findChild<LoopbackDialog *>(QStringLiteral("loopbackDialog"));
        if (dialog)
            dialog->start();
        return dialog;
    }
    return nullptr;
}

Connection *MainWindow::currentConnection() const
{
    return m_connectionsPanel->currentConnection();
}

Connection *MainWindow::openConnection(const SavedConnection &saved, bool remember)
{
    Connection *c = m_manager->open(saved);
    if (remember) {
        // Only a link that came up is worth remembering: a typo in the address or a refused
        // port must not fill Recent.
        auto once = std::make_shared<QMetaObject::Connection>();
        *once = connect(c, &Connection::linkStateChanged, this,
                        [this, c, saved, once](LinkState state) {
                            if (state != LinkState::Connected)
                                return;
                            QObject::disconnect(*once);
                            SavedConnection remembered = saved;
                            remembered.station = c->station();
                            m_manager->addRecent(remembered);
                        });
    }
    showStatus(tr("Connecting to %1 (%2)…").arg(c->name(), CoreText::settings(c->settings())));
    return c;
}

void MainWindow::newConnectionDialog()
{
    ConnectionDialog dialog(m_manager->recent(), this);
    if (dialog.exec() == QDialog::Accepted)
        openConnection(dialog.connection());
}

void MainWindow::closeCurrentConnection()
{
    Connection *c = currentConnection();
    if (!c)
        return;
    if (const int pending = c->session()->pendingWrites(); pending > 0)
        showStatus(
            tr("Closing %1: sending %n queued write(s) first (at most %2 s)…", nullptr, pending)
                .arg(c->name())
                .arg((c->session()->closeDrainMs() + 999) / 1000));
    m_manager->remove(c);
}

void MainWindow::rebuildRecentMenu()
{
    m_recentMenu->clear();
    const QList<SavedConnection> recent = m_manager->recent();
    for (const SavedConnection &c : recent) {
        m_recentMenu->addAction(
            tr("%1 — %2, station %3").arg(c.name, CoreText::settings(c.settings)).arg(c.station),
            this, [this, c] { openConnection(c); });
    }
    if (const int unreadable = m_manager->unreadableRecent(); unreadable > 0) {
        m_recentMenu->addSeparator();
        m_recentMenu
            ->addAction(tr("%n saved connection(s) could not be read (kept unchanged)", nullptr,
                           unreadable))
            ->setEnabled(false);
    }
    m_recentMenu->setEnabled(!m_recentMenu->isEmpty());
}

WatchTableWidget *MainWindow::addWatchTable(const QString &name)
{
    auto *table = new WatchTableWidget(m_manager, m_tabs);
    table->setName(name.isEmpty() ? tr("Watch %1").arg(++m_tableCounter) : name);
    if (Connection *c = currentConnection())
        table->setConnection(c);
    if (m_confirm)
        table->setConfirmHandler(m_confirm);
    connect(table, &WatchTableWidget::statusMessage, this, &MainWindow::showStatus);
    connect(table, &WatchTableWidget::addToTrendRequested, this,
            [this, table](const QList<int> &rows) { addToTrend(table, rows); });
    connect(table, &WatchTableWidget::nameChanged, this, [this, table](const QString &text) {
        m_tabs->setTabText(m_tabs->indexOf(table), text);
    });
    connect(table, &WatchTableWidget::connectionChanged, this, [this, table](Connection *c) {
        if (table == currentWatchTable())
            followTable(c);
    });
    m_tabs->addTab(table, QIcon(QStringLiteral(":/icons/table.svg")), table->name());
    return table;
}

WatchTableWidget *MainWindow::currentWatchTable() const
{
    return qobject_cast<WatchTableWidget *>(m_tabs->currentWidget());
}

QList<WatchTableWidget *> MainWindow::watchTables() const
{
    QList<WatchTableWidget *> list;
    for (int i = 0; i < m_tabs->count(); ++i) {
        if (auto *t = qobject_cast<WatchTableWidget *>(m_tabs->widget(i)))
            list.append(t);
    }
    return list;
}

void MainWindow::closeWatchTable(int index)
{
    QWidget *w = m_tabs->widget(index);
    if (!w)
        return;
    m_tabs->removeTab(index);
    w->deleteLater();
}

void MainWindow::renameWatchTable(int index)
{
    auto *table = qobject_cast<WatchTableWidget *>(m_tabs->widget(index));
    if (!table)
        return;
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Rename Watch Table"), tr("Name:"),
                                               QLineEdit::Normal, table->name(), &ok);
    if (ok && !name.trimmed().isEmpty())
        table->setName(name.trimmed());
}

Status MainWindow::saveWatchList(const QString &path) const
{
    WatchListFile file;
    for (WatchTableWidget *t : watchTables())
        file.tables.append(t->spec());
    Status s = WatchList::saveToFile(file, path);
    if (s) {
        QSettings().setValue(lastListKey, QFileInfo(path).absoluteFilePath());
        const_cast<MainWindow *>(this)->markWatchListSaved(path);
    }
    return s;
}

Status MainWindow::loadWatchList(const QString &path)
{
    const auto file = WatchList::loadFromFile(path);
    if (!file)
        return file.error();
    while (m_tabs->count() > 0)
        closeWatchTable(0);
    for (const WatchTableSpec &spec : file->tables)
        addWatchTable(spec.name)->setSpec(spec);
    if (m_tabs->count() == 0)
        addWatchTable();
    QSettings().setValue(lastListKey, QFileInfo(path).absoluteFilePath());
    markWatchListSaved(path);
    return Ok{};
}

bool MainWindow::restoreLastWatchList()
{
    QSettings settings;
    const QString path = settings.value(lastListKey).toString();
    if (!settings.value(reopenKey, true).toBool() || path.isEmpty() || !QFileInfo::exists(path))
        return false;
    if (const Status s = loadWatchList(path); !s) {
        showStatus(tr("The last watch list %1 cannot be loaded: %2")
                       .arg(QDir::toNativeSeparators(path), CoreText::message(s.error().message)));
        return false;
    }
    showStatus(tr("Reopened %1.").arg(QDir::toNativeSeparators(path)));
    return true;
}

Status MainWindow::openAtStartup(const std::optional<SavedConnection> &connection,
                                 const QString &path)
{
    Connection *c = connection ? openConnection(*connection) : nullptr;
    Status loaded = Ok{};
    if (!path.isEmpty()) {
        loaded = loadWatchList(path);
        if (!loaded) {
            // The words of File > Open; not modal, so the window (and --screenshot) carries on.
            auto *box = new QMessageBox(
                QMessageBox::Warning, tr("Open Watch List"),
                tr("%1 cannot be loaded:\n%2")
                    .arg(QFileInfo(path).fileName(), CoreText::message(loaded.error().message)),
                QMessageBox::Ok, this);
            box->setAttribute(Qt::WA_DeleteOnClose);
            box->open();
        } else {
            showStatus(tr("Loaded %1.").arg(QDir::toNativeSeparators(path)));
        }
    }
    if (c) {
        for (WatchTableWidget *t : watchTables())
            t->setConnection(c);
    }
    return loaded;
}

Status MainWindow::importCsv(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return makeError(ErrorKind::InvalidRequest,
                         tr("Cannot open %1: %2").arg(path, f.errorString()).toStdString());
    const auto rows = WatchList::importCsv(f.readAll());
    if (!rows)
        return rows.error();
    WatchTableWidget *table = currentWatchTable() ? currentWatchTable() : addWatchTable();
    table->model()->addItems(*rows);
    return Ok{};
}

void MainWindow::openWatchListDialog()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Watch List"), lastDirectory(),
                                                      tr("Watch lists (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    setLastDirectory(path);
    if (const Status s = loadWatchList(path); !s) {
        QMessageBox::warning(
            this, tr("Open Watch List"),
            tr("%1 cannot be loaded:\n%2")
                .arg(QFileInfo(path).fileName(), CoreText::message(s.error().message)));
        return;
    }
    showStatus(tr("Loaded %1.").arg(QDir::toNativeSeparators(path)));
}

bool MainWindow::saveWatchListDialog()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Save Watch List"),
                                                m_listPath.isEmpty() ? lastDirectory() : m_listPath,
                                                tr("Watch lists (*.json)"));
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    setLastDirectory(path);
    if (const Status s = saveWatchList(path); !s) {
        QMessageBox::warning(this, tr("Save Watch List"), CoreText::message(s.error().message));
        return false;
    }
    showStatus(tr("Saved %1.").arg(QDir::toNativeSeparators(path)));
    return true;
}

WatchListFile MainWindow::currentWatchList() const
{
    WatchListFile file;
    for (WatchTableWidget *t : watchTables())
        file.tables.append(t->spec());
    return file;
}

void MainWindow::markWatchListSaved(const QString &path)
{
    m_listPath = path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath();
    m_savedList = currentWatchList();
    updateWindowTitle();
}

bool MainWindow::isWatchListModified() const
{
    return currentWatchList() != m_savedList;
}

void MainWindow::updateWindowTitle()
{
    // The platform adds the application name ("… — FATEK Studio"): the title names the document.
    const QString list = m_listPath.isEmpty() ? tr("Untitled") : QFileInfo(m_listPath).fileName();
    setWindowTitle(m_readOnly ? tr("%1 — Operator mode (read-only)").arg(list) : list);
    setWindowFilePath(m_listPath);
}

bool MainWindow::confirmQuit()
{
    const bool unsaved = isWatchListModified();
    const bool logging = m_tableLogger && m_tableLogger->isLogging();
    if (!unsaved && !logging)
        return true;
    QStringList what;
    if (unsaved)
        what << tr("The watch list %1 has changes that are not saved.")
                    .arg(m_listPath.isEmpty() ? tr("(untitled)")
                                              : QDir::toNativeSeparators(m_listPath));
    if (logging)
        what << tr("Data logging to %1 is running; quitting stops it.")
                    .arg(QDir::toNativeSeparators(m_tableLogger->path()));
    QMessageBox box(QMessageBox::Question, tr("Quit FATEK Studio"), what.join(QLatin1Char('\n')),
                    QMessageBox::NoButton, this);
    box.setObjectName(QStringLiteral("quitQuestionBox"));
    QPushButton *save = nullptr;
    if (unsaved) {
        save = box.addButton(tr("&Save and Quit"), QMessageBox::AcceptRole);
        save->setObjectName(QStringLiteral("saveButton"));
    }
    QPushButton *quit
        = box.addButton(unsaved ? tr("Quit &Without Saving") : tr("Stop Logging and &Quit"),
                        QMessageBox::DestructiveRole);
    quit->setObjectName(QStringLiteral("quitButton"));
    QPushButton *cancel = box.addButton(QMessageBox::Cancel);
    cancel->setObjectName(QStringLiteral("cancelButton"));
    // The safe answer is the default: Enter saves, or keeps the window open.
    box.setDefaultButton(save ? save : cancel);
    box.setEscapeButton(cancel);
    box.exec();
    if (box.clickedButton() == quit)
        return true;
    if (save && box.clickedButton() == save)
        return m_listPath.isEmpty() ? saveWatchListDialog() : bool(saveWatchList(m_listPath));
    return false;
}

void MainWindow::importCsvDialog()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Import CSV"), lastDirectory(),
                                                      tr("CSV files (*.csv *.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    setLastDirectory(path);
    if (const Status s = importCsv(path); !s) {
        QMessageBox::warning(
            this, tr("Import CSV"),
            tr("%1 cannot be imported:\n%2")
                .arg(QFileInfo(path).fileName(), CoreText::message(s.error().message)));
        return;
    }
    showStatus(tr("Imported %1.").arg(QDir::toNativeSeparators(path)));
}

QString MainWindow::lastDirectory() const
{
    return QSettings().value(directoryKey).toString();
}

void MainWindow::setLastDirectory(const QString &path)
{
    QSettings().setValue(directoryKey, QFileInfo(path).absolutePath());
}

void MainWindow::startDemo()
{
    if (m_demo)
        return;
    m_demo = new DemoSimulator(this);
    connect(m_demo, &DemoSimulator::failed, this, [this](const QString &reason) {
        showStatus(tr("The demo simulator could not start: %1").arg(reason));
    });
    connect(m_demo, &DemoSimulator::ready, this, [this](quint16 port) {
        SavedConnection saved;
        saved.name = tr("Demo PLC");
        saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), port);
        saved.station = 1;
        // The port changes every run: not worth a recent entry.
        Connection *c = openConnection(saved, false);
        WatchTableWidget *table = currentWatchTable();
        if (!table || table->model()->rowCount() > 0)
            table = addWatchTable();
        table->setConnection(c);
        table->setSpec(DemoSimulator::demoTable(saved.station));
        m_tabs->setCurrentWidget(table);
        markWatchListSaved({}); // the demo's own table: nothing of the user's to save yet
        Q_EMIT demoReady();
    });
    m_demo->start();
    showStatus(tr("Starting the demo simulator…"));
}

bool MainWindow::hasValues() const
{
    for (WatchTableWidget *t : watchTables()) {
        const WatchTableModel *m = t->model();
        for (int r = 0; r < m->rowCount(); ++r) {
            if (m->hasValue(r))
                return true;
        }
    }
    return false;
}

void MainWindow::setConfirmHandler(ConfirmHandler handler)
{
    m_confirm = std::move(handler);
    for (WatchTableWidget *t : watchTables())
        t->setConfirmHandler(m_confirm);
}

void MainWindow::updateLinkStatus()
{
    const Connection *c = currentConnection();
    if (!c) {
        m_reconnectAction->setEnabled(false);
        m_linkStatus->setText(tr("No connection"));
        m_linkStatus->setToolTip({});
        return;
    }
    const StationStatistics &t = c->statistics().total;
    const LinkState state = c->linkState();
    m_reconnectAction->setEnabled(state != LinkState::Connected && state != LinkState::Connecting);
    if (state != LinkState::Connected) {
        // A link that is down has no rate or round trip worth showing: say why and how often.
        QString text = tr("%1: %2").arg(c->name(), c->stateText());
        if (c->linkFailures() > 0)
            text += tr(" · %n failed attempt(s)", nullptr, static_cast<int>(c->linkFailures()));
        if (state == LinkState::Reconnecting || state == LinkState::Lost)
            text += tr(" · F5 reconnects now");
        m_linkStatus->setText(text);
    } else {
        m_linkStatus->setText(
            tr("%1: %2 · %3 req/s · %4 errors · RTT %5")
                .arg(c->name(), c->stateText())
                .arg(c->requestsPerSecond(), 0, 'f', 1)
                .arg(c->errorCount())
                .arg(t.answers ? tr("%1 ms").arg(t.rttMeanMs, 0, 'f', 1) : QStringLiteral("–")));
    }
    m_linkStatus->setToolTip(c->linkReason().isEmpty()
                                 ? CoreText::settings(c->settings())
                                 : CoreText::settings(c->settings()) + QLatin1Char('\n')
                                       + CoreText::message(c->linkReason()));
}

void MainWindow::followTable(Connection *connection)
{
    // A table without a connection leaves the choice as it is (new tables take the current one).
    if (connection && connection != currentConnection())
        m_connectionsPanel->setCurrentConnection(connection);
}

void MainWindow::updateToolTargets()
{
    Connection *c = currentConnection();
    const quint8 station = c ? c->station() : quint8(1);
    if (m_toolsInitialised && c == m_toolConnection && station == m_toolStation)
        return;
    m_toolsInitialised = true;
    m_toolConnection = c;
    m_toolStation = station;
    for (const auto &setTarget : std::as_const(m_toolTargets))
        setTarget(c ? c->session() : nullptr, c ? c->station() : quint8(1),
                  c ? c->name() : QString());
}

void MainWindow::showStatus(const QString &text)
{
    statusBar()->showMessage(text, 10000);
}

bool MainWindow::settlePendingWritesBeforeQuit()
{
    const QList<Connection *> connections = m_manager->connections();
    int pending = 0;
    int drainMs = 0;
    for (Connection *c : connections) {
        pending += c->session()->pendingWrites();
        drainMs = std::max(drainMs, c->session()->closeDrainMs());
    }
    if (pending == 0)
        return true;
    const int seconds = (drainMs + 999) / 1000;
    QMessageBox box(QMessageBox::Warning, tr("Writes not sent yet"),
                    tr("%n write(s) to the PLC have not been sent yet.", nullptr, pending),
                    QMessageBox::NoButton, this);
    box.setObjectName(QStringLiteral("pendingWritesBox"));
    box.setInformativeText(tr("Wait for them (at most %n second(s)), or drop them? Dropped writes "
                              "never reach the PLC.",
                              nullptr, seconds));
    QPushButton *wait = box.addButton(tr("&Wait and Quit"), QMessageBox::AcceptRole);
    wait->setObjectName(QStringLiteral("waitButton"));
    QPushButton *drop = box.addButton(tr("&Drop and Quit"), QMessageBox::DestructiveRole);
    drop->setObjectName(QStringLiteral("dropButton"));
    QPushButton *cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(wait);
    box.setEscapeButton(cancel);
    box.exec();
    if (box.clickedButton() == drop) {
        for (Connection *c : connections)
            c->session()->close(CloseMode::Discard);
        return true;
    }
    if (box.clickedButton() != wait)
        return false;
    // Non-blocking: the links drain while the window stays responsive; it closes when they are
    // all closed (each bounded by its drain time).
    m_quitting = true;
    showStatus(tr("Sending %n queued write(s) before quitting (at most %1 s)…", nullptr, pending)
                   .arg(seconds));
    for (Connection *c : connections) {
        connect(c, &Connection::linkStateChanged, this, [this](LinkState state) {
            if (state != LinkState::Closed)
                return;
            const QList<Connection *> all = m_manager->connections();
            if (std::all_of(all.begin(), all.end(), [](const Connection *other) {
                    return other->linkState() == LinkState::Closed;
                }))
                close();
        });
        c->close();
    }
    return false;
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    // Unsaved tables and a running log first, as editors do; then writes not sent yet.
    if (!m_quitting && !m_quitConfirmed) {
        if (!confirmQuit()) {
            event->ignore();
            return;
        }
        m_quitConfirmed = true;
    }
    const QList<Connection *> connections = m_manager->connections();
    const bool quitNow
        = m_quitting
              ? std::all_of(connections.begin(), connections.end(),
                            [](Connection *c) { return c->linkState() == LinkState::Closed; })
              : settlePendingWritesBeforeQuit();
    if (!quitNow) {
        if (!m_quitting)
            m_quitConfirmed = false; // Cancel on the writes question: ask again next time
        event->ignore();
        return;
    }
    m_quitConfirmed = false; // a window shown again asks again
    stopLogging();           // the log file is complete when the window goes
    QSettings settings;
    settings.setValue(geometryKey, saveGeometry());
    settings.setValue(stateKey, saveState());
    QMainWindow::closeEvent(event);
}

} // namespace Fatek
