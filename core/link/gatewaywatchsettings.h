#pragma once

#include "core/mqtt/mqttbrokersettings.h"

#include <QString>

namespace Fatek {

// Where a gateway publishes one of its connections: the broker, the topic prefix and the
// gateway's connection name (GatewayTopics).
struct GatewayWatchSettings
{
    MqttBrokerSettings broker;
    QString prefix = QStringLiteral("fatek");
    QString connection;

    // Empty when usable, else what to fix (the broker's settings, the prefix, the name).
    Message validate() const;
    bool operator==(const GatewayWatchSettings &) const = default;
};

} // namespace Fatek
