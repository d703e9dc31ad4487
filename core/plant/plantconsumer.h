#pragma once

#include "core/session/sessiontypes.h"
#include "core/watch/itemassembler.h"

#include <QList>

namespace Fatek {

// One user of a plant connection's values: a watch table, the gateway's MQTT side, and what comes
// next (alarms, history, an OPC UA server). It subscribes its items to a PlantConnection and
// receives their values, and nothing of any other consumer's. Called in the plant connection's
// thread, never from inside subscribe(); a consumer that lives elsewhere hands on through a queued
// signal (PlantSubscription). A consumer unsubscribes before it is destroyed.
class PlantConsumer
{
public:
    PlantConsumer() = default;
    PlantConsumer(const PlantConsumer &) = delete;
    PlantConsumer &operator=(const PlantConsumer &) = delete;
    virtual ~PlantConsumer() = default;

    // The values of this consumer's items that one poll cycle (or one burst of messages) reported.
    virtual void plantValues(const QList<WatchItemValue> &values) = 0;
    // The link's state changed (its items' values stop coming while it is down).
    virtual void plantLinkState(LinkState state, const Message &reason)
    {
        Q_UNUSED(state);
        Q_UNUSED(reason);
    }
};

} // namespace Fatek
