#include "closedtables.h"

#include "mainwindow.h"
#include "ui/connection/connection.h"
#include "ui/watch/watchtablewidget.h"

#include <QAction>
#include <QMenu>
#include <QTabBar>
#include <QTabWidget>

#include <algorithm>

namespace Fatek {

ClosedTables::ClosedTables(MainWindow *window, QTabWidget *tabs, QMenu *watchMenu)
    : QObject(window)
    , m_window(window)
    , m_tabs(tabs)
{
    m_reopen = watchMenu->addAction(tr("&Reopen Closed Table"), this, &ClosedTables::reopen);
    m_reopen->setObjectName(QStringLiteral("reopenClosedTableAction"));
    m_reopen->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T));
    updateAction();
}

void ClosedTables::remember(const WatchTableWidget *table, int index)
{
    Closed closed;
    closed.spec = table->spec();
    closed.connection = table->connection();
    closed.index = index;
    m_closed.append(closed);
    while (m_closed.size() > kept)
        m_closed.removeFirst();
    updateAction();
    Q_EMIT statusMessage(
        tr("Closed \u201c%1\u201d (%n row(s)): %2 reopens it.", nullptr,
           static_cast<int>(closed.spec.items.size()))
            .arg(closed.spec.name, m_reopen->shortcut().toString(QKeySequence::NativeText)));
}

void ClosedTables::forget()
{
    m_closed.clear();
    updateAction();
}

void ClosedTables::reopen()
{
    if (m_closed.isEmpty())
        return;
    const Closed closed = m_closed.takeLast();
    WatchTableWidget *table = m_window->addWatchTable(closed.spec.name);
    table->setSpec(closed.spec);
    // Its own connection when it is still open; else the table takes the current one, as a new
    // table does.
    if (closed.connection)
        table->setConnection(closed.connection);
    const int to = std::clamp(closed.index, 0, m_tabs->count() - 1);
    m_tabs->tabBar()->moveTab(m_tabs->indexOf(table), to);
    m_tabs->setCurrentWidget(table);
    updateAction();
    Q_EMIT statusMessage(tr("Reopened \u201c%1\u201d (%n row(s)).", nullptr,
                            static_cast<int>(closed.spec.items.size()))
                             .arg(closed.spec.name));
}

void ClosedTables::updateAction()
{
    m_reopen->setEnabled(!m_closed.isEmpty());
    m_reopen->setStatusTip(m_closed.isEmpty()
                               ? tr("No watch table was closed")
                               : tr("Open \u201c%1\u201d again, with its rows and settings")
                                     .arg(m_closed.constLast().spec.name));
    m_reopen->setToolTip(m_reopen->statusTip());
}

} // namespace Fatek
