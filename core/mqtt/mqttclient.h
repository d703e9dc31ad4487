#pragma once

#include "core/qtbridge/qtmessage.h"
#include "mqttbrokersettings.h"

#include <QByteArray>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>

namespace Fatek {

struct MqttClientShared;

// One connection to an MQTT broker (MQTT 3.1.1 through libmosquitto). The network runs on a thread
// of its own that connects, keeps the link alive and reconnects with backoff (reconnectMinMs,
// doubled up to reconnectMaxMs); signals come on this object's thread. Subscriptions are made again
// on every reconnect. Every public function is thread-safe and returns at once.
class MqttClient : public QObject
{
    Q_OBJECT

public:
    explicit MqttClient(const MqttBrokerSettings &settings, QObject *parent = nullptr);
    // Disconnects cleanly (the broker does not send the will) and stops the network thread.
    ~MqttClient() override;

    MqttBrokerSettings settings() const;

    // The message the broker publishes for this client when its link dies without a clean
    // disconnect (the gateway's "offline" status). Set before open().
    void setWill(const QString &topic, const QByteArray &payload, int qos = 1, bool retain = true);
    // The same with a payload made again before every (re)connect, on the network thread (so
    // `payload` must not touch anything but its own copies): a will that says when it was made.
    void setWill(const QString &topic, std::function<QByteArray()> payload, int qos = 1,
                 bool retain = true);
    // Subscribed on every (re)connect; adding one while connected subscribes at once.
    void subscribe(const QString &filter, int qos = 0);

    // Starts connecting; false (and nothing started) when the settings are not usable: see
    // openError().
    bool open();
    Message openError() const;
    // A clean DISCONNECT (no will); messages not yet written are dropped. open() starts again.
    void close();

    bool isConnected() const;
    // Hands a message to the library; false when not connected (the caller keeps or drops it) or
    // the library refused it. QoS 0 or 1.
    //
    // Messages wait in this client's queue while the library still has packets the socket did not
    // take (a slow or stalled broker): there a retained QoS 0 message replaces the one waiting for
    // the same topic (only the newest state goes, superseded() counts the replaced ones), so that
    // nothing but one batch waits in the library, and the queue holds at most one message per
    // retained topic besides the rest.
    bool publish(const QString &topic, const QByteArray &payload, int qos = 0, bool retain = false);
    // The same with the topic in UTF-8 (a caller that keeps its topics encoded: no conversion per
    // message).
    bool publishUtf8(const QByteArray &topic, const QByteArray &payload, int qos = 0,
                     bool retain = false);
    // Messages handed over and not yet written to the socket: the caller's back-pressure.
    int outstanding() const;
    // Retained QoS 0 messages replaced in the queue by a newer one for the same topic.
    quint64 superseded() const;
    // At most `batches` batches of received messages on their way to this object's thread (0: no
    // bound, the default). While that many wait, the network thread reads nothing more: the
    // socket and then the broker hold the rest, and a broker drops QoS 0 messages beyond its queue
    // limit (mosquitto: max_queued_messages), so a reader slower than the flood gets recent
    // messages instead of an ever older backlog. Only for a reader that may lose QoS 0 messages
    // (live values); a long stall also delays the keep-alive's answers. Set before open().
    void setReceiveWindow(int batches);

Q_SIGNALS:
    void connected();
    // The link to the broker went down, or a connection attempt failed (reason says which); the
    // network thread tries again after the backoff delay.
    void disconnected(const Fatek::Message &reason);
    // `queued`: the broker kept it for this client's persistent session while the client was
    // away (it may be old: a command's sender may have given up).
    void messageReceived(const QString &topic, const QByteArray &payload, bool retained,
                         bool queued);

private:
    std::shared_ptr<MqttClientShared> m_shared;
};

} // namespace Fatek
