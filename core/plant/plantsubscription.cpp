#include "plantsubscription.h"

#include "plantconnection.h"

namespace Fatek {

PlantSubscription::PlantSubscription(QObject *parent)
    : QObject(parent)
{}

PlantSubscription::~PlantSubscription()
{
    if (m_connection)
        m_connection->unsubscribe(this);
}

void PlantSubscription::setConnection(PlantConnection *connection)
{
    if (connection == m_connection)
        return;
    if (m_connection)
        m_connection->unsubscribe(this);
    m_connection = connection;
    if (m_connection)
        m_connection->subscribe(this, m_items);
}

void PlantSubscription::setItems(const QList<WatchedItem> &items)
{
    m_items = items;
    if (m_connection)
        m_connection->subscribe(this, m_items);
}

void PlantSubscription::plantValues(const QList<WatchItemValue> &values)
{
    Q_EMIT itemValues(values);
}

void PlantSubscription::plantLinkState(LinkState state, const Message &reason)
{
    Q_EMIT linkStateChanged(state, reason);
}

} // namespace Fatek
