#pragma once

#include "gatewayconfig.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>

#include <vector>

namespace Fatek {

// Home Assistant's MQTT discovery for the items of one connection (docs/gateway.md): one retained
// config message per item under <discovery prefix>/<component>/<node id>/<object id>/config, so
// that Home Assistant creates the entities itself and marks them unavailable when the gateway or
// the PLC link is down (availability on the connection's status topic, which also carries the
// gateway's will) or when the item is not good (availability on the item's own topic).
//   binary_sensor  a bit item (a discrete, or a register shown as a bit)
//   switch         ... that the gateway may write (every element allowlisted, not read-only)
//   sensor         any other item (numbers; ascii as text)
//   number         a register item the gateway may write, in a format written as a decimal
//                  (signed, unsigned, float, double; hex, binary and bcd stay sensors)
// and a binary_sensor (device class "problem") per alarm, on while the alarm is active, with the
// alarm's state payload as its attributes.
namespace HomeAssistantDiscovery {

struct Entry
{
    QString topic;
    QByteArray payload;
};

// The config messages of every item of `connection` (each followed by its alarms'), in watch
// list order.
std::vector<Entry> entries(const QString &discoveryPrefix, const QString &prefix,
                           const GatewayConnectionConfig &connection, bool readOnly);

// The config of one alarm of `spec` (an entities() entry).
Entry alarmEntry(const QString &discoveryPrefix, const QString &prefix, const QString &connection,
                 const QString &nodeId, const QJsonObject &device, const WatchItemSpec &spec,
                 const AlarmDefinition &alarm);

// A topic level Home Assistant takes as node or object id: letters, digits, '_' and '-' only.
QString idLevel(const QString &text);

} // namespace HomeAssistantDiscovery

} // namespace Fatek
