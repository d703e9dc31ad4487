#pragma once

#include "core/protocol/result.h"
#include "tooldocks.h"
#include "ui/connection/linksettingsio.h"
#include "ui/trend/trendlogging.h"
#include "ui/watch/watchtablewidget.h"
#include "watchlistdocument.h"

#include <QMainWindow>

#include <optional>

class QLabel;
class QMenu;
class QTabWidget;

namespace Fatek {

class AlarmsUi;
class HistoryUi;
class Connection;
class ConnectionManager;
class ConnectionsPanel;
class DemoSimulator;
class LinkStatusLabel;

// The main window composes: the connections panel, the watch table tabs and their file
// (WatchListDocument), the tool docks (ToolDocks), trends and data logging (TrendLogging), menus,
// shortcuts and the status bar. Polling, parsing and formatting live in the parts it composes.
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    explicit MainWindow(bool readOnly = false, QWidget *parent = nullptr);
    ~MainWindow() override;

    ConnectionManager *connections() const { return m_manager; }
    Connection *currentConnection() const;
    // What the tools act on: the connection of the table in front, else the current one.
    Connection *toolConnection() const;
    bool isReadOnly() const { return m_readOnly; }

    // Opens a connection (and remembers it as recent unless `remember` is false).
    Connection *openConnection(const SavedConnection &saved, bool remember = true);

    WatchTableWidget *addWatchTable(const QString &name = {});
    WatchTableWidget *currentWatchTable() const;
    QList<WatchTableWidget *> watchTables() const;

    // Replaces every table by tables made from `specs` (one empty table when there are none).
    void replaceWatchTables(const QList<WatchTableSpec> &specs);

    // Watch list files (all tables, see WatchListDocument).
    Status saveWatchList(const QString &path) const { return m_document->save(path); }
    Status loadWatchList(const QString &path) { return m_document->load(path); }
    Status importCsv(const QString &path) { return m_document->importCsv(path); }
    // File > Import Names and Comments… without its file dialog (see WatchListDocument).
    Result<SymbolImport> importNames(const QString &path) { return m_document->importNames(path); }
    const SymbolNames *symbolNames() const { return m_document->symbols(); }
    bool restoreLastWatchList() { return m_document->restoreLast(); }
    // Start-up from the command line (fatek-studio --tcp ... FILE): opens `connection` (if given)
    // as File > New Connection does, loads the watch list `path` (if not empty) as File > Open
    // does, and binds every table to that connection. A file that cannot be loaded is reported in
    // the window as File > Open reports it (without blocking) and returned.
    Status openAtStartup(const std::optional<SavedConnection> &connection, const QString &path);

    // Starts the embedded simulator and opens the demo table on it; demoReady() when connected.
    void startDemo();
    // Opens a commissioning tool: "control", "forcing", "console" (docks), "loopback" (dialog,
    // started at once), "trend", or "connection" (the New Connection dialog, not blocking).
    // Returns the tool's widget, or nullptr for an unknown name.
    QWidget *openTool(const QString &name);
    // Whether any table shows a value read from a PLC.
    bool hasValues() const;

    // Every table (present and future) asks this instead of showing a dialog (tests).
    void setConfirmHandler(ConfirmHandler handler);

Q_SIGNALS:
    void demoReady();

protected:
    void closeEvent(QCloseEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    void createActions();
    void newConnectionDialog();
    void closeCurrentConnection();
    void rebuildRecentMenu();
    // Close Table: undone by Watch > Reopen Closed Table (ClosedTables).
    void closeWatchTable(int index);
    // Removes the tab and deletes its table (closing, or a watch list replacing the tables).
    void removeWatchTable(int index);
    void renameWatchTable(int index);
    void updateLinkStatus();
    void updateToolTargets();
    // Makes the connection of the table in front the current one.
    void followTable(Connection *connection);
    void showStatus(const QString &text);
    // Brings the window (its frame too) inside the screen's available area: the default size
    // and a geometry saved on a larger screen would put the status bar below a laptop's screen.
    void fitIntoScreen();

public:
    // Trends and data logging (see TrendLogging).
    TrendView *trendView() const { return m_trend->trendView(); }
    TableLogger *tableLogger() const { return m_trend->tableLogger(); }
    // Logs the current watch table to `path` (CSV, appended); a log already running stops first.
    Status startLogging(const QString &path) { return m_trend->startLogging(path); }
    void stopLogging() { m_trend->stopLogging(); }
    // Alarms: the summary dock, the status bar's count, the journal, the tables' definitions.
    AlarmsUi *alarms() const { return m_alarms; }
    // History: what the tables record, the store the trend reads.
    HistoryUi *history() const { return m_history; }

private:
    // Every session, present and future, follows the mode (enforced there); the tools re-read it.
    void applyOperatorMode(bool active);

    bool m_readOnly;
    ConnectionManager *m_manager;
    ConnectionsPanel *m_connectionsPanel;
    QDockWidget *m_connectionsDock;
    QTabWidget *m_tabs;
    LinkStatusLabel *m_linkStatus = nullptr;
    QMenu *m_recentMenu = nullptr;
    QAction *m_reconnectAction = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_toolsMenu = nullptr;
    DemoSimulator *m_demo = nullptr;
    ConfirmHandler m_confirm;
    WatchListDocument *m_document;
    // Asked before the window closes (unsaved list, running log, writes not sent).
    class QuitQuestions *m_quitQuestions;
    ToolDocks *m_tools = nullptr;
    TrendLogging *m_trend = nullptr;
    AlarmsUi *m_alarms = nullptr;
    HistoryUi *m_history = nullptr;
    class ClosedTables *m_closedTables = nullptr;
    int m_tableCounter = 0;
    class OperatorMode *m_operatorMode = nullptr;
};

} // namespace Fatek
