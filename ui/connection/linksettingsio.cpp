#include "linksettingsio.h"

#include "ui/common/uitext.h"

#include <QCoreApplication>

namespace Fatek {

QString SavedConnection::linkText() const
{
    if (!gateway)
        return UiText::settings(settings);
    // "MQTT gateway line1 on mqtt://broker:1883 (prefix fatek)".
    return QCoreApplication::translate("Fatek::SavedConnection",
                                       "MQTT gateway %1 on %2 (prefix %3)")
        .arg(gateway->connection, gateway->broker.toUrl(), gateway->prefix);
}

namespace LinkSettingsIo {

namespace {

template<typename E>
int toInt(E value)
{
    return static_cast<int>(value);
}

template<typename E>
E toEnum(const QVariant &value, E fallback, int count)
{
    bool ok = false;
    const int v = value.toInt(&ok);
    return (ok && v >= 0 && v < count) ? static_cast<E>(v) : fallback;
}

} // namespace

QVariantMap toMap(const SavedConnection &c)
{
    const LinkSettings &s = c.settings;
    QVariantMap m;
    m[QStringLiteral("name")] = c.name;
    m[QStringLiteral("station")] = c.station;
    m[QStringLiteral("kind")] = toInt(s.kind);
    m[QStringLiteral("host")] = s.host;
    m[QStringLiteral("port")] = s.port;
    m[QStringLiteral("portName")] = s.portName;
    m[QStringLiteral("baudRate")] = s.baudRate;
    m[QStringLiteral("dataBits")] = s.dataBits;
    m[QStringLiteral("parity")] = toInt(s.parity);
    m[QStringLiteral("stopBits")] = s.stopBits;
    m[QStringLiteral("flowControl")] = toInt(s.flowControl);
    m[QStringLiteral("protocol")] = toInt(s.protocol);
    m[QStringLiteral("timeoutMs")] = s.timeoutMs;
    m[QStringLiteral("retries")] = s.retries;
    if (c.gateway) {
        const MqttBrokerSettings &b = c.gateway->broker;
        QVariantMap g;
        g[QStringLiteral("broker")] = b.toUrl(); // scheme, user, host, port; no password
        g[QStringLiteral("caFile")] = b.caFile;
        // Paths only: the key's content stays in its file.
        g[QStringLiteral("certFile")] = b.certFile;
        g[QStringLiteral("keyFile")] = b.keyFile;
        g[QStringLiteral("prefix")] = c.gateway->prefix;
        g[QStringLiteral("connection")] = c.gateway->connection;
        m[QStringLiteral("gateway")] = g;
    }
    return m;
}

SavedConnection fromMap(const QVariantMap &m)
{
    SavedConnection c;
    LinkSettings &s = c.settings;
    c.name = m.value(QStringLiteral("name")).toString();
    const int station = m.value(QStringLiteral("station"), 1).toInt();
    c.station = static_cast<quint8>(station >= 0 && station <= 254 ? station : 1);
    s.kind = toEnum(m.value(QStringLiteral("kind")), s.kind, 3);
    s.host = m.value(QStringLiteral("host"), s.host).toString();
    const int port = m.value(QStringLiteral("port"), s.port).toInt();
    if (port > 0 && port <= 65535)
        s.port = static_cast<quint16>(port);
    s.portName = m.value(QStringLiteral("portName"), s.portName).toString();
    s.baudRate = m.value(QStringLiteral("baudRate"), s.baudRate).toInt();
    s.dataBits = m.value(QStringLiteral("dataBits"), s.dataBits).toInt();
    s.parity = toEnum(m.value(QStringLiteral("parity")), s.parity, 3);
    s.stopBits = m.value(QStringLiteral("stopBits"), s.stopBits).toInt();
    s.flowControl = toEnum(m.value(QStringLiteral("flowControl")), s.flowControl, 3);
    s.protocol = toEnum(m.value(QStringLiteral("protocol")), s.protocol, 3);
    s.timeoutMs = m.value(QStringLiteral("timeoutMs"), s.timeoutMs).toInt();
    s.retries = m.value(QStringLiteral("retries"), s.retries).toInt();
    const QVariant gateway = m.value(QStringLiteral("gateway"));
    if (gateway.typeId() == QMetaType::QVariantMap) {
        const QVariantMap g = gateway.toMap();
        const Result<MqttBrokerSettings> broker
            = MqttBrokerSettings::fromUrl(g.value(QStringLiteral("broker")).toString());
        GatewayWatchSettings settings;
        if (broker.ok())
            settings.broker = *broker;
        settings.broker.caFile = g.value(QStringLiteral("caFile")).toString();
        settings.broker.certFile = g.value(QStringLiteral("certFile")).toString();
        settings.broker.keyFile = g.value(QStringLiteral("keyFile")).toString();
        settings.prefix = g.value(QStringLiteral("prefix"), settings.prefix).toString();
        settings.connection = g.value(QStringLiteral("connection")).toString();
        c.gateway = settings;
    }
    return c;
}

} // namespace LinkSettingsIo

} // namespace Fatek
