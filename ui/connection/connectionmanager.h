#pragma once

#include "connection.h"

#include <QList>
#include <QObject>

namespace Fatek {

// The open connections of the window and the recent ones (QSettings). Applies operator mode to
// every session, present and future.
class ConnectionManager : public QObject
{
    Q_OBJECT

public:
    explicit ConnectionManager(QObject *parent = nullptr);
    ~ConnectionManager() override;

    QList<Connection *> connections() const { return m_connections; }
    Connection *connection(int index) const { return m_connections.value(index); }
    int indexOf(const Connection *connection) const;
    Connection *find(const QString &name) const;

    // Creates and opens a connection; a name already in use gets " (2)", " (3)" ...
    Connection *open(const SavedConnection &saved);
    void remove(Connection *connection);

    void setReadOnly(bool readOnly);
    bool isReadOnly() const { return m_readOnly; }

    // Most recent first, at most maxRecent; stored in QSettings under "connections/recent".
    QList<SavedConnection> recent() const;
    // Stored entries that are not a connection at all (damaged settings): not listed, and kept
    // as they are when the list is saved again, never dropped silently.
    int unreadableRecent() const;
    void addRecent(const SavedConnection &saved);
    static constexpr int maxRecent = 10;

Q_SIGNALS:
    void connectionAdded(Fatek::Connection *connection);
    void connectionAboutToBeRemoved(Fatek::Connection *connection);
    void connectionRemoved(Fatek::Connection *connection);
    void connectionChanged(Fatek::Connection *connection);
    void recentChanged();

private:
    QString uniqueName(const QString &name) const;

    QList<Connection *> m_connections;
    bool m_readOnly = false;
};

} // namespace Fatek
