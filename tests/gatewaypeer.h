#pragma once

#include "core/mqtt/gatewaypayload.h"
#include "core/mqtt/mqttbrokersettings.h"
#include "core/watch/watchlist.h"

#include <QList>
#include <QObject>
#include <QString>

#include <optional>
#include <vector>

namespace Fatek {
class MqttClient;
}

namespace TestUtil {

// The gateway's side of the topic scheme for tests of its readers: an MQTT client that publishes
// item values and the link status (retained, again after every reconnect, with the "offline"
// will) and answers write commands on /set as the gateway does. A protocol peer on a real broker,
// not the gateway program.
class GatewayPeer : public QObject
{
    Q_OBJECT

public:
    GatewayPeer(const Fatek::MqttBrokerSettings &broker, const QString &prefix,
                const QString &connection, QObject *parent = nullptr);
    ~GatewayPeer() override;

    bool open();
    bool isConnected() const;

    // Publishes (and republishes after reconnects) `item` with its elements' words.
    void setItem(const Fatek::WatchItemSpec &item, const std::vector<std::uint32_t> &words,
                 Fatek::ValueQuality quality = Fatek::ValueQuality::Good,
                 const Fatek::Message &error = {});
    void setStatus(Fatek::GatewayPayload::LinkStatus state, const Fatek::Message &reason = {});

    // Commands received on any /set topic of the connection, decodable or not.
    int setCount() const { return m_setCount; }
    QList<Fatek::GatewayPayload::SetCommand> commands() const { return m_commands; }
    // Answering: off = silence (the reader times out); a refusal answers ok false with it.
    void setAnswering(bool answering) { m_answering = answering; }
    void setRefusal(const Fatek::Message &refusal) { m_refusal = refusal; }

private:
    struct Item
    {
        Fatek::WatchItemSpec spec;
        std::vector<std::uint32_t> words;
        Fatek::ValueQuality quality;
        Fatek::Message error;
    };
    void publishAll();
    void publishItem(const Item &item);
    void onMessage(const QString &topic, const QByteArray &payload);

    QString m_prefix;
    QString m_connection;
    Fatek::MqttClient *m_client;
    QList<Item> m_items;
    Fatek::GatewayPayload::Status m_status;
    int m_setCount = 0;
    QList<Fatek::GatewayPayload::SetCommand> m_commands;
    bool m_answering = true;
    Fatek::Message m_refusal;
};

} // namespace TestUtil
