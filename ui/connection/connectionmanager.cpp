#include "connectionmanager.h"

#include <QSettings>

namespace Fatek {

namespace {

const QString recentKey = QStringLiteral("connections/recent");

// Splits the stored list into connections and entries that are not one (kept verbatim).
QList<SavedConnection> readRecent(QVariantList *unreadable)
{
    QList<SavedConnection> list;
    const QVariantList stored = QSettings().value(recentKey).toList();
    for (const QVariant &v : stored) {
        SavedConnection c;
        if (v.typeId() == QMetaType::QVariantMap)
            c = LinkSettingsIo::fromMap(v.toMap());
        if (!c.name.isEmpty())
            list.append(c);
        else if (unreadable)
            unreadable->append(v);
    }
    return list;
}

} // namespace

ConnectionManager::ConnectionManager(QObject *parent)
    : QObject(parent)
{
    registerSessionMetaTypes();
}

ConnectionManager::~ConnectionManager()
{
    // Sessions stop their threads in their destructors; do it before the QObject tree goes.
    const QList<Connection *> all = m_connections;
    m_connections.clear();
    qDeleteAll(all);
}

int ConnectionManager::indexOf(const Connection *connection) const
{
    for (int i = 0; i < m_connections.size(); ++i) {
        if (m_connections.at(i) == connection)
            return i;
    }
    return -1;
}

Connection *ConnectionManager::find(const QString &name) const
{
    for (Connection *c : m_connections) {
        if (c->name() == name)
            return c;
    }
    return nullptr;
}

QString ConnectionManager::uniqueName(const QString &name) const
{
    const QString base = name.trimmed().isEmpty() ? QStringLiteral("PLC") : name.trimmed();
    QString candidate = base;
    for (int n = 2; find(candidate); ++n)
        candidate = QStringLiteral("%1 (%2)").arg(base).arg(n);
    return candidate;
}

Connection *ConnectionManager::open(const SavedConnection &saved)
{
    SavedConnection named = saved;
    named.name = uniqueName(saved.name);
    auto *connection = new Connection(named, this);
    connection->setReadOnly(m_readOnly);
    connect(connection, &Connection::changed, this,
            [this, connection] { Q_EMIT connectionChanged(connection); });
    m_connections.append(connection);
    // Open first: whoever reacts to connectionAdded (tools reading the PLC status) may submit at
    // once, and requests wait while the link connects but fail on a closed one.
    connection->open();
    Q_EMIT connectionAdded(connection);
    return connection;
}

void ConnectionManager::remove(Connection *connection)
{
    const int index = indexOf(connection);
    if (index < 0)
        return;
    Q_EMIT connectionAboutToBeRemoved(connection);
    m_connections.removeAt(index);
    Q_EMIT connectionRemoved(connection);
    if (connection->pendingWrites() == 0 || connection->linkState() == LinkState::Closed) {
        delete connection;
        return;
    }
    // Writes it accepted leave first (bounded by the session's drain time); the window does not
    // wait for them.
    connect(connection, &Connection::linkStateChanged, connection, [connection](LinkState state) {
        if (state == LinkState::Closed)
            connection->deleteLater();
    });
    connection->close();
}

void ConnectionManager::setReadOnly(bool readOnly)
{
    m_readOnly = readOnly;
    for (Connection *c : std::as_const(m_connections))
        c->setReadOnly(readOnly);
}

QList<SavedConnection> ConnectionManager::recent() const
{
    return readRecent(nullptr);
}

int ConnectionManager::unreadableRecent() const
{
    QVariantList unreadable;
    readRecent(&unreadable);
    return static_cast<int>(unreadable.size());
}

void ConnectionManager::addRecent(const SavedConnection &saved)
{
    QVariantList unreadable;
    QList<SavedConnection> list = readRecent(&unreadable);
    list.removeIf([&](const SavedConnection &c) { return c.name == saved.name; });
    list.prepend(saved);
    while (list.size() > maxRecent)
        list.removeLast();
    QVariantList stored;
    for (const SavedConnection &c : std::as_const(list))
        stored.append(LinkSettingsIo::toMap(c));
    stored.append(unreadable); // after the connections, unchanged
    QSettings().setValue(recentKey, stored);
    Q_EMIT recentChanged();
}

} // namespace Fatek
