#pragma once

#include "linksettingsio.h"
#include "result.h"
#include "watchtablewidget.h"

#include <QMainWindow>
#include <QPointer>

#include <optional>

class QDockWidget;
class QKeySequence;
class QLabel;
class QMenu;
class QTabWidget;

namespace Fatek {

class Connection;
class ConnectionManager;
class ConnectionsPanel;
class DemoSimulator;
class Session;
class TableLogger;
class TrendView;

// The main window composes: the connections panel, the watch table tabs, the tool docks, menus,
// shortcuts and the status bar. Polling, parsing and formatting live in the parts it composes.
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    explicit MainWindow(bool readOnly = false, QWidget *parent = nullptr);
    ~MainWindow() override;

    ConnectionManager *connections() const { return m_manager; }
    Connection *currentConnection() const;
    bool isReadOnly() const { return m_readOnly; }

    // Opens a connection (and remembers it as recent unless `remember` is false).
    Connection *openConnection(const SavedConnection &saved, bool remember = true);

    WatchTableWidget *addWatchTable(const QString &name = {});
    WatchTableWidget *currentWatchTable() const;
    QList<WatchTableWidget *> watchTables() const;

    // Watch list files (all tables); load replaces the tables only if the file is valid.
    Status saveWatchList(const QString &path) const;
    Status loadWatchList(const QString &path);
    // CSV rows into the current table.
    Status importCsv(const QString &path);
    // Opens the watch list saved or opened last (when that preference is on); false if none.
    bool restoreLastWatchList();
    // Start-up from the command line (fatek-studio --tcp ... FILE): opens `connection` (if given)
    // as File > New Connection does, loads the watch list `path` (if not empty) as File > Open
    // does, and binds every table to that connection. A file that cannot be loaded is reported in
    // the window as File > Open reports it (without blocking) and returned.
    Status openAtStartup(const std::optional<SavedConnection> &connection, const QString &path);

    // Starts the embedded simulator and opens the demo table on it; demoReady() when connected.
    void startDemo();
    // Opens a commissioning tool: "control", "forcing", "console" (docks) or "loopback" (dialog,
    // started at once). Returns the tool's widget, or nullptr for an unknown name.
    QWidget *openTool(const QString &name);
    // Whether any table shows a value read from a PLC.
    bool hasValues() const;

    // Every table (present and future) asks this instead of showing a dialog (tests).
    void setConfirmHandler(ConfirmHandler handler);

Q_SIGNALS:
    void demoReady();

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    // Quitting with writes not sent yet: asks to wait for them or drop them; false: stay open.
    bool settlePendingWritesBeforeQuit();
    void createActions();
    void createTools();
    // A Tools/View menu entry with a shortcut that shows and raises `dock`, or hides it when it
    // is already in front.
    QAction *dockAction(QDockWidget *dock, const QKeySequence &shortcut);
    void newConnectionDialog();
    void closeCurrentConnection();
    void rebuildRecentMenu();
    void closeWatchTable(int index);
    void renameWatchTable(int index);
    void openWatchListDialog();
    // false when cancelled or failed
    bool saveWatchListDialog();
    WatchListFile currentWatchList() const;
    // The tables as saved to (or loaded from) `path` (empty: untitled); the title follows.
    void markWatchListSaved(const QString &path);
    bool isWatchListModified() const;
    void updateWindowTitle();
    // Asks before quitting with unsaved tables or a running data log; false: stay open.
    bool confirmQuit();
    void importCsvDialog();
    void updateLinkStatus();
    void updateToolTargets();
    // Makes the connection of the table in front the current one (the tools' target).
    void followTable(Connection *connection);
    void showStatus(const QString &text);
    QString lastDirectory() const;
    void setLastDirectory(const QString &path);

public:
    // Trends and data logging (ui/trend, defined in ui/trend/mainwindowtrend.cpp).
    TrendView *trendView() const { return m_trendView; }
    TableLogger *tableLogger() const { return m_tableLogger; }
    // Adds rows of a watch table to the trend and shows the trend.
    void addToTrend(WatchTableWidget *table, const QList<int> &rows);
    // Logs the current watch table to `path` (CSV, appended); a log already running stops first.
    Status startLogging(const QString &path);
    void stopLogging();

private:
    void createTrendAndLogging();
    QWidget *showTrend();
    void startLoggingDialog();
    void updateLoggingStatus();
    void createOperatorMode();
    void applyOperatorMode(bool active);
    void updateModeLabel(bool active);

    bool m_readOnly;
    // Quit chosen, links draining their queued writes: the window closes once they are closed.
    bool m_quitting = false;
    // The unsaved-tables/logging question was answered for this quit.
    bool m_quitConfirmed = false;
    QString m_listPath;
    WatchListFile m_savedList;
    ConnectionManager *m_manager;
    ConnectionsPanel *m_connectionsPanel;
    QTabWidget *m_tabs;
    QLabel *m_linkStatus;
    QLabel *m_modeLabel = nullptr;
    QMenu *m_recentMenu = nullptr;
    QAction *m_reconnectAction = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_toolsMenu = nullptr;
    DemoSimulator *m_demo = nullptr;
    ConfirmHandler m_confirm;
    // Commissioning tools follow the current connection and station.
    QList<std::function<void(Session *, quint8, const QString &)>> m_toolTargets;
    QPointer<Connection> m_toolConnection;
    quint8 m_toolStation = 1;
    bool m_toolsInitialised = false;
    int m_tableCounter = 0;
    TrendView *m_trendView = nullptr;
    QDockWidget *m_trendDock = nullptr;
    TableLogger *m_tableLogger = nullptr;
    QLabel *m_loggingLabel = nullptr;
    QAction *m_startLoggingAction = nullptr;
    QAction *m_stopLoggingAction = nullptr;
    class OperatorMode *m_operatorMode = nullptr;
};

} // namespace Fatek
