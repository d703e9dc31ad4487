#pragma once

#include "core/watch/watchlist.h"

#include <QList>
#include <QObject>
#include <QPointer>

class QAction;
class QMenu;
class QTabWidget;

namespace Fatek {

class Connection;
class MainWindow;
class WatchTableWidget;

// Closing a watch table is undone, as a browser undoes closing a tab: Close Table (Ctrl+F4, the
// tab's ×) closes at once, without a question, the status bar says how to get it back, and
// Watch > Reopen Closed Table (Ctrl+Shift+T) brings back the last one closed with its rows, names,
// alarms, settings and connection, at its old place. Repeated, it goes further back.
class ClosedTables : public QObject
{
    Q_OBJECT

public:
    ClosedTables(MainWindow *window, QTabWidget *tabs, QMenu *watchMenu);

    // Keeps what `table` (at tab `index`, about to be closed) holds.
    void remember(const WatchTableWidget *table, int index);
    // Another watch list replaces the tables: what was closed from the old one is not offered.
    void forget();
    int count() const { return static_cast<int>(m_closed.size()); }
    QAction *reopenAction() const { return m_reopen; }

Q_SIGNALS:
    void statusMessage(const QString &text);

private:
    void reopen();
    void updateAction();

    struct Closed
    {
        WatchTableSpec spec;
        QPointer<Connection> connection;
        int index = 0;
    };
    // Newest last; a browser keeps about as many.
    static constexpr int kept = 25;

    MainWindow *m_window;
    QTabWidget *m_tabs;
    QAction *m_reopen;
    QList<Closed> m_closed;
};

} // namespace Fatek
