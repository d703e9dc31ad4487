#pragma once

#include "plantconsumer.h"

#include <QList>
#include <QObject>
#include <QPointer>

namespace Fatek {

class PlantConnection;

// A consumer for QObject code (a watch table): subscribes its items to one plant connection at a
// time and hands their values on as a signal. Moving to another connection takes the items along;
// destroying it unsubscribes.
class PlantSubscription : public QObject, public PlantConsumer
{
    Q_OBJECT

public:
    explicit PlantSubscription(QObject *parent = nullptr);
    ~PlantSubscription() override;

    PlantConnection *connection() const { return m_connection; }
    void setConnection(PlantConnection *connection);
    // Replaces the items (an empty list watches nothing).
    void setItems(const QList<WatchedItem> &items);
    QList<WatchedItem> items() const { return m_items; }

    void plantValues(const QList<WatchItemValue> &values) override;
    void plantLinkState(LinkState state, const Message &reason) override;

Q_SIGNALS:
    void itemValues(const QList<Fatek::WatchItemValue> &values);
    void linkStateChanged(Fatek::LinkState state, const Fatek::Message &reason);

private:
    QPointer<PlantConnection> m_connection;
    QList<WatchedItem> m_items;
};

} // namespace Fatek
