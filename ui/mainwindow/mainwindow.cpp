#include "mainwindow.h"

#include "operatormode.h"
#include "quitquestions.h"

#include "closedtables.h"
#include "demosimulator.h"
#include "helpmenu.h"
#include "languagemenu.h"
#include "linkstatuslabel.h"
#include "ui/alarm/alarmjournaldialog.h"
#include "ui/alarm/alarmsui.h"
#include "ui/common/uitext.h"
#include "ui/connection/connectiondialog.h"
#include "ui/connection/connectionmanager.h"
#include "ui/connection/connectionspanel.h"
#include "ui/history/historyui.h"
#include "ui/tools/forcingpanel.h"
#include "ui/trend/tablelogger.h"
#include "ui/trend/trendview.h"
#include "ui/watch/watchtablemodel.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QInputDialog>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
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
} // namespace

MainWindow::MainWindow(bool readOnly, QWidget *parent)
    : QMainWindow(parent)
    , m_readOnly(readOnly)
    , m_manager(new ConnectionManager(this))
    , m_document(new WatchListDocument(this))
    , m_quitQuestions(new QuitQuestions(this, m_manager, m_document))
{
    initStudioResources();
    setObjectName(QStringLiteral("mainWindow"));
    setWindowIcon(QIcon(QStringLiteral(":/icons/fatek-studio.svg")));
    m_manager->setReadOnly(readOnly);
    connect(m_quitQuestions, &QuitQuestions::statusMessage, this, &MainWindow::showStatus);

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
        updateToolTargets();
    });
    connect(m_tabs->tabBar(), &QTabBar::tabBarDoubleClicked, this, &MainWindow::renameWatchTable);

    m_connectionsPanel = new ConnectionsPanel(m_manager, this);
    m_connectionsDock = new QDockWidget(tr("Connections"), this);
    m_connectionsDock->setObjectName(QStringLiteral("connectionsDock"));
    m_connectionsDock->setWidget(m_connectionsPanel);
    addDockWidget(Qt::BottomDockWidgetArea, m_connectionsDock);

    m_linkStatus = new LinkStatusLabel(this);
    statusBar()->addPermanentWidget(m_linkStatus);

    connect(m_document, &WatchListDocument::statusMessage, this, &MainWindow::showStatus);
    createActions();
    m_tools = new ToolDocks(this, m_connectionsDock, m_toolsMenu, m_viewMenu);
    connect(m_tools, &ToolDocks::statusMessage, this, &MainWindow::showStatus);
    for (ForcingPanel *forcing : findChildren<ForcingPanel *>()) // made by ToolDocks
        forcing->setSymbols(m_document->symbols());
    addWatchTable();
    m_document->markSaved({});

    connect(m_connectionsPanel, &ConnectionsPanel::currentConnectionChanged, this, [this] {
        updateLinkStatus();
        updateToolTargets();
    });
    connect(m_manager, &ConnectionManager::connectionChanged, this, [this](Connection *c) {
        if (c == currentConnection())
            updateLinkStatus();
        if (c == currentConnection() || c == toolConnection())
            updateToolTargets(); // the station may have changed
    });
    connect(m_manager, &ConnectionManager::recentChanged, this, &MainWindow::rebuildRecentMenu);
    connect(m_manager, &ConnectionManager::connectionAdded, this, [this](Connection *c) {
        connect(c, &Connection::linkStateChanged, this,
                [this, c](LinkState state, const Message &reason) {
                    showStatus(
                        reason.empty()
                            ? tr("%1: %2").arg(c->name(), UiText::linkState(state))
                            : tr("%1: %2 (%3)")
                                  .arg(c->name(), UiText::linkState(state), translated(reason)));
                });
    });

    resize(1280, 800);
    // Tall enough for the raw console's send line and its answer (its tab shares this area).
    resizeDocks({m_connectionsDock}, {13 * fontMetrics().lineSpacing()}, Qt::Vertical);
    QSettings settings;
    restoreGeometry(settings.value(geometryKey).toByteArray());
    restoreState(settings.value(stateKey).toByteArray());
    fitIntoScreen();
}

void MainWindow::fitIntoScreen()
{
    const QScreen *screen = this->screen();
    if (!screen || isMaximized() || isFullScreen())
        return;
    const QRect available = screen->availableGeometry();
    QRect frame = frameGeometry();
    QMargins margins(geometry().left() - frame.left(), geometry().top() - frame.top(),
                     frame.right() - geometry().right(), frame.bottom() - geometry().bottom());
    // Before the first show the frame is not known yet: allow for a title bar and borders.
    if (!isVisible() && margins.isNull()) {
        const int border = style()->pixelMetric(QStyle::PM_DefaultFrameWidth) + 2;
        margins = QMargins(border, style()->pixelMetric(QStyle::PM_TitleBarHeight) + border, border,
                           border);
    }
    const QSize room = available.size().shrunkBy(margins);
    const QSize size = this->size().boundedTo(room).expandedTo(minimumSize());
    if (size != this->size())
        resize(size);
    frame = QRect(geometry().topLeft(), size).marginsAdded(margins);
    const QPoint inside(
        std::clamp(frame.left(), available.left(),
                   std::max(available.left(), available.right() - frame.width() + 1)),
        std::clamp(frame.top(), available.top(),
                   std::max(available.top(), available.bottom() - frame.height() + 1)));
    if (inside != frame.topLeft())
        move(inside); // move() places the frame
}

void MainWindow::resizeEvent(QResizeEvent *event)
{
    QMainWindow::resizeEvent(event);
    if (m_linkStatus)
        m_linkStatus->setRoom(width() - 240); // a message keeps some room beside it
    // A dock shown or moved may have grown the window past the screen on its way (Qt grows a
    // window to its minimum, and never shrinks it back): once the layout has settled, fit it.
    if (isVisible())
        QMetaObject::invokeMethod(this, &MainWindow::fitIntoScreen, Qt::QueuedConnection);
}

void MainWindow::showEvent(QShowEvent *event)
{
    QMainWindow::showEvent(event);
    // Now the window system knows the frame: place it again if it does not fit.
    fitIntoScreen();
}

MainWindow::~MainWindow()
{
    // Tear down in dependency order: tools and tables hold sessions, the connections panel reads
    // the manager, the manager owns the sessions.
    disconnect(m_connectionsPanel, nullptr, this, nullptr);
    disconnect(m_manager, nullptr, this, nullptr);
    disconnect(m_tabs, nullptr, this, nullptr);
    m_tools->releaseTargets();
    delete m_alarms; // its engines leave the plant connections before the manager goes
    m_alarms = nullptr;
    trendView()->setHistoryCenter(nullptr);
    delete m_history; // so do its recorders; then its store writes what is pending
    m_history = nullptr;
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
    m_recentMenu->setToolTipsVisible(true);
    rebuildRecentMenu();
    auto *disconnectAction
        = file->addAction(QIcon(QStringLiteral(":/icons/disconnect.svg")), tr("&Close Connection"),
                          this, &MainWindow::closeCurrentConnection);
    disconnectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_W));
    m_reconnectAction = file->addAction(tr("Reconn&ect Now"), this, [this] {
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
    m_document->addFileActions(file);
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
    m_closedTables = new ClosedTables(this, m_tabs, watch);
    connect(m_closedTables, &ClosedTables::statusMessage, this, &MainWindow::showStatus);

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        m_viewMenu->addAction(dock->toggleViewAction());
    m_viewMenu->addAction(toolBar->toggleViewAction());

    m_toolsMenu = menuBar()->addMenu(tr("&Tools"));
    m_trend = new TrendLogging(
        this, m_connectionsDock, [this] { return currentWatchTable(); }, m_toolsMenu, m_viewMenu);
    connect(m_trend, &TrendLogging::statusMessage, this, &MainWindow::showStatus);
    // The demo shows its sine wave and its ramp in the trend from the start.
    connect(this, &MainWindow::demoReady, m_trend, &TrendLogging::showDemo);
    m_alarms = new AlarmsUi(this, m_connectionsDock, m_manager, m_toolsMenu, m_viewMenu);
    connect(m_alarms, &AlarmsUi::statusMessage, this, &MainWindow::showStatus);
    m_history = new HistoryUi(this, m_manager);
    connect(m_history, &HistoryUi::statusMessage, this, &MainWindow::showStatus);
    trendView()->setHistoryCenter(m_history->center());
    m_operatorMode = new OperatorMode(m_readOnly, this);
    m_toolsMenu->addSeparator();
    m_toolsMenu->addAction(m_operatorMode->toggleAction());
    m_toolsMenu->addAction(m_operatorMode->passwordAction());
    statusBar()->addPermanentWidget(m_operatorMode->label());
    connect(m_operatorMode, &OperatorMode::activeChanged, this, &MainWindow::applyOperatorMode);
    connect(m_operatorMode, &OperatorMode::message, this, &MainWindow::showStatus);
    applyOperatorMode(m_operatorMode->isActive()); // the stored preference
    m_viewMenu->addSeparator();
    m_viewMenu->addMenu(new LanguageMenu(m_viewMenu));

    new HelpMenu(this);

    toolBar->addAction(connectAction);
    toolBar->addAction(disconnectAction);
    toolBar->addSeparator();
    toolBar->addAction(newTable);
    toolBar->addAction(m_document->openAction());
    toolBar->addAction(m_document->saveAction());
    toolBar->addAction(pause);
}

QWidget *MainWindow::openTool(const QString &name)
{
    if (name == QLatin1String("trend"))
        return m_trend->showTrend();
    if (name == QLatin1String("alarms"))
        return m_alarms->showSummary();
    if (name == QLatin1String("journal"))
        return m_alarms->showJournal();
    if (name == QLatin1String("connection")) {
        // The New Connection dialog, shown without blocking so that --screenshot can grab it.
        auto *dialog = new ConnectionDialog(m_manager->recent(), this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        connect(dialog, &QDialog::accepted, this,
                [this, dialog] { openConnection(dialog->connection()); });
        dialog->show();
        return dialog;
    }
    return m_tools->openTool(name);
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
    showStatus(tr("Connecting to %1 (%2)…").arg(c->name(), c->linkText()));
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
    if (const int pending = c->pendingWrites(); pending > 0)
        showStatus(
            tr("Closing %1: sending %n queued write(s) first (at most %2 s)…", nullptr, pending)
                .arg(c->name())
                .arg((c->closeDrainMs() + 999) / 1000));
    m_manager->remove(c);
}

void MainWindow::rebuildRecentMenu()
{
    m_recentMenu->clear();
    const QList<SavedConnection> recent = m_manager->recent();
    for (const SavedConnection &c : recent) {
        QAction *action = m_recentMenu->addAction(
            tr("%1 — %2, station %3").arg(c.name, c.linkText()).arg(c.station), this,
            [this, c] { openConnection(c); });
        // The link as fatek-cli --link takes it.
        if (!c.gateway)
            action->setToolTip(c.settings.toUrl(c.station));
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
    table->model()->setSymbols(m_document->symbols());
    table->setName(name.isEmpty() ? tr("Watch %1").arg(++m_tableCounter) : name);
    if (Connection *c = currentConnection())
        table->setConnection(c);
    if (m_confirm)
        table->setConfirmHandler(m_confirm);
    connect(table, &WatchTableWidget::statusMessage, this, &MainWindow::showStatus);
    m_alarms->addTable(table);
    m_history->addTable(table);
    connect(table, &WatchTableWidget::edited, m_document, &WatchListDocument::updateModified);
    connect(table, &WatchTableWidget::addToTrendRequested, this,
            [this, table](const QList<int> &rows) { m_trend->addToTrend(table, rows); });
    connect(table, &WatchTableWidget::nameChanged, this, [this, table](const QString &text) {
        m_tabs->setTabText(m_tabs->indexOf(table), text);
    });
    connect(table, &WatchTableWidget::connectionChanged, this, [this, table](Connection *c) {
        if (table == currentWatchTable()) {
            followTable(c);
            updateToolTargets();
        }
    });
    m_tabs->addTab(table, QIcon(QStringLiteral(":/icons/table.svg")), table->name());
    m_document->updateModified();
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
    // No question, as a browser closes a tab: Watch > Reopen Closed Table undoes it.
    if (auto *table = qobject_cast<WatchTableWidget *>(m_tabs->widget(index)))
        m_closedTables->remember(table, index);
    removeWatchTable(index);
}

void MainWindow::removeWatchTable(int index)
{
    QWidget *w = m_tabs->widget(index);
    if (!w)
        return;
    m_tabs->removeTab(index);
    w->deleteLater();
    m_document->updateModified();
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

void MainWindow::replaceWatchTables(const QList<WatchTableSpec> &specs)
{
    while (m_tabs->count() > 0)
        removeWatchTable(0);
    m_closedTables->forget(); // tables of the list that was replaced
    for (const WatchTableSpec &spec : specs)
        addWatchTable(spec.name)->setSpec(spec);
    if (m_tabs->count() == 0)
        addWatchTable();
}

Status MainWindow::openAtStartup(const std::optional<SavedConnection> &connection,
                                 const QString &path)
{
    Connection *c = connection ? openConnection(*connection) : nullptr;
    Status loaded = Ok{};
    if (!path.isEmpty())
        loaded = m_document->open(path);
    if (c) {
        for (WatchTableWidget *t : watchTables())
            t->setConnection(c);
    }
    return loaded;
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
        m_document->markSaved({}); // the demo's own table: nothing of the user's to save yet
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
    const LinkState state = c ? c->linkState() : LinkState::Closed;
    m_reconnectAction->setEnabled(c && state != LinkState::Connected
                                  && state != LinkState::Connecting);
    m_linkStatus->showConnection(c);
}

void MainWindow::followTable(Connection *connection)
{
    // A table without a connection leaves the choice as it is (new tables take the current one).
    if (connection && connection != currentConnection())
        m_connectionsPanel->setCurrentConnection(connection);
}

Connection *MainWindow::toolConnection() const
{
    // The PLC the person sees named in the table in front; a connection added meanwhile becomes
    // the panel's current one (new tables take it) but must not retarget RUN/STOP or forcing.
    if (const WatchTableWidget *t = currentWatchTable(); t && t->connection())
        return t->connection();
    return currentConnection();
}

void MainWindow::updateToolTargets()
{
    if (m_tools) // not yet while the menus are made
        m_tools->setTarget(toolConnection());
}

void MainWindow::showStatus(const QString &text)
{
    // Left of the link summary: a longer message is elided, whole in the tooltip (the summary
    // covered it).
    const int room = statusBar()->width() - m_linkStatus->sizeHint().width() - 30;
    statusBar()->showMessage(
        isVisible() ? statusBar()->fontMetrics().elidedText(text, Qt::ElideRight, room) : text,
        10000);
    statusBar()->setToolTip(text);
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (!m_quitQuestions->mayClose()) {
        event->ignore();
        return;
    }
    stopLogging(); // the log file is complete when the window goes
    QSettings settings;
    settings.setValue(geometryKey, saveGeometry());
    settings.setValue(stateKey, saveState());
    QMainWindow::closeEvent(event);
}

void MainWindow::applyOperatorMode(bool active)
{
    m_readOnly = active;
    m_manager->setReadOnly(active);
    for (WatchTableWidget *table : watchTables()) {
        if (!active)
            table->operatorModeEnded();
    }
    m_document->updateWindowTitle();
    if (m_tools)
        m_tools->setTarget(toolConnection(), true);
}

} // namespace Fatek
