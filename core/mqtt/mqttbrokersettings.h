#pragma once

#include "core/protocol/result.h"

#include <QString>

namespace Fatek {

// Where the broker is and how to log in: a plain value type.
struct MqttBrokerSettings
{
    QString host = QStringLiteral("127.0.0.1");
    quint16 port = 1883;
    bool tls = false;
    // TLS: the CA certificate that signed the broker's (empty: the system's CA folder), and an
    // optional client certificate and key.
    QString caFile;
    QString certFile;
    QString keyFile;
    // TLS without checking the broker's host name (test brokers with a self-signed certificate).
    bool tlsInsecure = false;
    QString username;
    QString password;
    // Empty: one is made up ("fatek-<host>-<pid>-<n>").
    QString clientId;
    // false: a persistent session (MQTT clean session off): with a fixed clientId the broker keeps
    // the subscriptions and queues QoS 1 messages while the client is away (the gateway's
    // commands, issue 33).
    bool cleanSession = true;
    int keepAliveSec = 30;
    // Reconnect: first delay, doubled after each failure up to the maximum.
    int reconnectMinMs = 500;
    int reconnectMaxMs = 30000;

    // mqtt://[user[:password]@]host[:port] (1883) or mqtts://... (TLS, 8883). A bare "host[:port]"
    // is mqtt://.
    static Result<MqttBrokerSettings> fromUrl(const QString &url);
    // The URL without the password ("mqtts://operator@broker:8883"): messages and the files the
    // studio saves may show it.
    QString toUrl() const;
    // Empty when usable, else what to fix (TLS files that do not exist or that libmosquitto would
    // not load, a key not of its certificate, TLS settings with an mqtt:// URL, a port of 0 ...).
    Message validate() const;
    // Whether this build's MQTT library can speak TLS (mqtts://): the Windows build's cannot
    // yet (docs/windows.md). validate() refuses TLS settings where it cannot.
    static bool tlsAvailable();

    bool operator==(const MqttBrokerSettings &) const = default;
};

} // namespace Fatek
