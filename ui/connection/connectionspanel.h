#pragma once

#include <QWidget>

class QTableView;

namespace Fatek {

class Connection;
class ConnectionListModel;
class ConnectionManager;

// Side panel: the open connections with state and statistics; the selected one is "current"
// (the tools act on it and new watch tables use it).
class ConnectionsPanel : public QWidget
{
    Q_OBJECT

public:
    explicit ConnectionsPanel(ConnectionManager *manager, QWidget *parent = nullptr);

    Connection *currentConnection() const;
    void setCurrentConnection(Connection *connection);
    QTableView *view() const { return m_view; }

Q_SIGNALS:
    // Also emitted when the station of the current connection changes.
    void currentConnectionChanged(Fatek::Connection *connection);

private:
    ConnectionManager *m_manager;
    ConnectionListModel *m_model;
    QTableView *m_view;
};

} // namespace Fatek
