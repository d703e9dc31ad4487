#include "homeassistantdiscovery.h"

#include "core/mqtt/gatewaytopics.h"
#include "core/watch/itemvalues.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace Fatek {

namespace {

// What the status topic's JSON says, reduced to the two words availability compares: only a
// link that is up makes its items available ("connecting", "down", "offline": not).
const QString StatusTemplate = QStringLiteral("{{ 'up' if value_json.state == 'up' else 'down' }}");
// An item is available while its own quality is good (stale or error: unavailable, its last
// value kept by Home Assistant but not shown as current).
const QString QualityTemplate
    = QStringLiteral("{{ 'good' if value_json.quality == 'good' else 'bad' }}");
// "value" is null until the item was read once: "None" is Home Assistant's "unknown".
const QString BitTemplate = QStringLiteral(
    "{{ 'None' if value_json.value is none else ('ON' if value_json.value else 'OFF') }}");
const QString ValueTemplate = QStringLiteral("{{ value_json.value }}");
// An alarm is on while active (acknowledged or not); shelved, returned or out of service: off.
const QString AlarmTemplate = QStringLiteral(
    "{{ 'ON' if value_json.state in ['activeUnacked', 'activeAcked'] else 'OFF' }}");
// An alarm's last state stays meaningful while the PLC link is down (a quality alarm says so):
// only a gateway that is gone (its will, or stopped) makes it unavailable.
const QString GatewayTemplate
    = QStringLiteral("{{ 'down' if value_json.state == 'offline' else 'up' }}");

bool isBit(const ItemValues &item)
{
    return item.width() == 1 || item.item().format == DisplayFormat::Bit;
}

bool isNumeric(DisplayFormat format)
{
    return format != DisplayFormat::Ascii && format != DisplayFormat::Bit;
}

// Formats whose /set text is the plain decimal a number entity sends ("26" is 0x26 for hex).
bool takesDecimal(DisplayFormat format)
{
    return format == DisplayFormat::Signed || format == DisplayFormat::Unsigned
           || format == DisplayFormat::Float32 || format == DisplayFormat::Double64;
}

// The range a number entity offers for the item's format and width (its default is 1..100).
std::pair<double, double> numberRange(const ItemValues &item)
{
    const int bits = item.width();
    switch (item.item().format) {
    case DisplayFormat::Float32: return {-3.4e38, 3.4e38};
    case DisplayFormat::Double64: return {-1.7e308, 1.7e308};
    case DisplayFormat::Signed: {
        const double half = std::ldexp(1.0, bits - 1);
        return {-half, half - 1};
    }
    default: return {0, std::ldexp(1.0, bits) - 1};
    }
}

} // namespace

HomeAssistantDiscovery::Entry
HomeAssistantDiscovery::alarmEntry(const QString &discoveryPrefix, const QString &prefix,
                                   const QString &connection, const QString &nodeId,
                                   const QJsonObject &device, const WatchItemSpec &spec,
                                   const AlarmDefinition &alarm)
{
    // A binary sensor per alarm (issue 50), its attributes the whole state payload (priority,
    // since, shelvedUntil, ...).
    const QString alarmId = Alarms::alarmId(spec, alarm.kind);
    const QString objectId = idLevel(QStringLiteral("alarm_") + alarmId);
    const QString topic = GatewayTopics::alarm(prefix, connection, alarmId);
    const QJsonObject config{
        {QStringLiteral("name"), Alarms::messageOf(spec, alarm)},
        {QStringLiteral("unique_id"), nodeId + u'_' + objectId},
        {QStringLiteral("object_id"), nodeId + u'_' + objectId},
        {QStringLiteral("device_class"), QStringLiteral("problem")},
        {QStringLiteral("state_topic"), topic},
        {QStringLiteral("value_template"), AlarmTemplate},
        {QStringLiteral("payload_on"), QStringLiteral("ON")},
        {QStringLiteral("payload_off"), QStringLiteral("OFF")},
        {QStringLiteral("json_attributes_topic"), topic},
        {QStringLiteral("availability"),
         QJsonArray{
             QJsonObject{{QStringLiteral("topic"), GatewayTopics::status(prefix, connection)},
                         {QStringLiteral("value_template"), GatewayTemplate},
                         {QStringLiteral("payload_available"), QStringLiteral("up")},
                         {QStringLiteral("payload_not_available"), QStringLiteral("down")}}}},
        {QStringLiteral("device"), device},
    };
    return {discoveryPrefix + QStringLiteral("/binary_sensor/") + nodeId + u'/' + objectId
                + QStringLiteral("/config"),
            QJsonDocument(config).toJson(QJsonDocument::Compact)};
}

QString HomeAssistantDiscovery::idLevel(const QString &text)
{
    QString id;
    for (const QChar c : text) {
        const bool plain = (c >= u'a' && c <= u'z') || (c >= u'A' && c <= u'Z')
                           || (c >= u'0' && c <= u'9') || c == u'_' || c == u'-';
        id += plain ? c : u'_';
    }
    return id;
}

std::vector<HomeAssistantDiscovery::Entry>
HomeAssistantDiscovery::entries(const QString &discoveryPrefix, const QString &prefix,
                                const GatewayConnectionConfig &connection, bool readOnly)
{
    const QString nodeId = idLevel(prefix + u'_' + connection.name);
    const QString statusTopic = GatewayTopics::status(prefix, connection.name);
    const QJsonObject device{
        {QStringLiteral("identifiers"), QJsonArray{QStringLiteral("fatek-gateway_") + nodeId}},
        {QStringLiteral("name"), connection.name},
        {QStringLiteral("manufacturer"), QStringLiteral("FATEK")},
        {QStringLiteral("model"), connection.link.toString()},
    };
    std::vector<Entry> result;
    for (const WatchTableSpec &table : connection.tables) {
        for (const WatchItemSpec &spec : table.items) {
            const ItemValues item(spec);
            bool writable = !readOnly;
            for (int i = 0; writable && i < item.elementCount(); ++i)
                writable = connection.allows(item.elementAddress(i));
            const QString address = QString::fromStdString(spec.address.toString());
            const QString objectId
                = idLevel(QStringLiteral("s%1_%2").arg(spec.station).arg(address));
            const QString itemTopic
                = GatewayTopics::item(prefix, connection.name, spec.station, spec.address);
            QJsonObject config{
                {QStringLiteral("name"), spec.name.isEmpty() ? address : spec.name},
                {QStringLiteral("unique_id"), nodeId + u'_' + objectId},
                {QStringLiteral("object_id"), nodeId + u'_' + objectId},
                {QStringLiteral("state_topic"), itemTopic},
                {QStringLiteral("availability_mode"), QStringLiteral("all")},
                {QStringLiteral("availability"),
                 QJsonArray{
                     QJsonObject{{QStringLiteral("topic"), statusTopic},
                                 {QStringLiteral("value_template"), StatusTemplate},
                                 {QStringLiteral("payload_available"), QStringLiteral("up")},
                                 {QStringLiteral("payload_not_available"), QStringLiteral("down")}},
                     QJsonObject{
                         {QStringLiteral("topic"), itemTopic},
                         {QStringLiteral("value_template"), QualityTemplate},
                         {QStringLiteral("payload_available"), QStringLiteral("good")},
                         {QStringLiteral("payload_not_available"), QStringLiteral("bad")}}}},
                {QStringLiteral("device"), device},
            };
            QString component;
            if (isBit(item)) {
                component = writable ? QStringLiteral("switch") : QStringLiteral("binary_sensor");
                config.insert(QStringLiteral("value_template"), BitTemplate);
                config.insert(QStringLiteral("payload_on"), QStringLiteral("ON"));
                config.insert(QStringLiteral("payload_off"), QStringLiteral("OFF"));
                if (writable) {
                    config.insert(QStringLiteral("state_on"), QStringLiteral("ON"));
                    config.insert(QStringLiteral("state_off"), QStringLiteral("OFF"));
                }
            } else {
                writable = writable && takesDecimal(spec.format);
                component = writable ? QStringLiteral("number") : QStringLiteral("sensor");
                config.insert(QStringLiteral("value_template"), ValueTemplate);
                if (isNumeric(spec.format) && !writable)
                    config.insert(QStringLiteral("state_class"), QStringLiteral("measurement"));
                if (writable) {
                    const auto [min, max] = numberRange(item);
                    const bool real = spec.format == DisplayFormat::Float32
                                      || spec.format == DisplayFormat::Double64;
                    config.insert(QStringLiteral("min"), min);
                    config.insert(QStringLiteral("max"), max);
                    config.insert(QStringLiteral("step"), real ? 0.001 : 1.0);
                    config.insert(QStringLiteral("mode"), QStringLiteral("box"));
                }
            }
            if (writable) {
                // The gateway's /set takes the plain text; its answer goes to /reply.
                config.insert(
                    QStringLiteral("command_topic"),
                    GatewayTopics::itemSet(prefix, connection.name, spec.station, spec.address));
                config.insert(QStringLiteral("qos"), 1);
            }
            result.push_back({discoveryPrefix + u'/' + component + u'/' + nodeId + u'/' + objectId
                                  + QStringLiteral("/config"),
                              QJsonDocument(config).toJson(QJsonDocument::Compact)});
            for (const AlarmDefinition &alarm : spec.alarms)
                result.push_back(alarmEntry(discoveryPrefix, prefix, connection.name, nodeId,
                                            device, spec, alarm));
        }
    }
    return result;
}

} // namespace Fatek
