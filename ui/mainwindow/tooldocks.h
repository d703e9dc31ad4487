#pragma once

#include <QHash>
#include <QList>
#include <QObject>
#include <QPointer>

#include <functional>

class QAction;
class QDockWidget;
class QKeySequence;
class QMenu;
class QWidget;

namespace Fatek {

class Connection;
class MainWindow;
class PlcTarget;

// The commissioning tools of the main window: the PLC Control, Forcing and Raw Console docks, the
// Loopback Test, Memory Snapshot, I/O Checkout and Scan Stations dialogs, and their Tools/View menu
// entries. Every tool acts on one target, MainWindow::toolConnection() and its station (the
// docks' titles name it).
class ToolDocks : public QObject
{
    Q_OBJECT

public:
    // Adds the docks to `window` (the side ones hidden; the console as a tab beside `tabWith`,
    // the connections dock) and the entries to the menus.
    ToolDocks(MainWindow *window, QDockWidget *tabWith, QMenu *toolsMenu, QMenu *viewMenu);

    // Opens a tool: "control", "forcing", "console" (docks), "loopback" (dialog, started at
    // once), "program", "snapshot" or "checkout" (dialogs, through their Tools actions). Returns
    // the tool's widget, or nullptr for another name.
    QWidget *openTool(const QString &name);
    // Points every tool (and open dialog) at `connection` (nullptr: none). Nothing happens when
    // it is the target already with the same station, unless `force` (a tool re-reads the
    // link's operator mode).
    void setTarget(Connection *connection, bool force = false);
    // Lets go of every link: the connections are about to go.
    void releaseTargets();

    // A Tools/View menu entry with a shortcut that shows and raises `dock`, or hides it when it
    // is already in front.
    static QAction *dockAction(QDockWidget *dock, const QKeySequence &shortcut, QObject *parent);
    // Why the tools are greyed out on a gateway connection.
    static QString gatewayNotice();

Q_SIGNALS:
    void statusMessage(const QString &text);

private:
    using SetTarget = std::function<void(const PlcTarget &)>;

    // Shows a tool dialog (deleted on close) aimed at the current connection, and keeps it aimed
    // at the current one: the Loopback Test, Program Backup / Restore and Memory Snapshot
    // dialogs.
    template<typename Dialog>
    void openDialog(Dialog *dialog, const QString &objectName);

    void showGatewayNotice(bool gateway);

    MainWindow *m_window;
    QList<QDockWidget *> m_docks;
    QList<QString> m_titles; // the docks' own titles, without the target
    // The dialogs' actions that need a PLC link, with their own tooltips.
    QHash<QAction *, QString> m_linkActions;
    QAction *m_loopbackAction = nullptr;
    QList<SetTarget> m_targets;
    QPointer<Connection> m_connection;
    quint8 m_station = 1;
};

} // namespace Fatek
