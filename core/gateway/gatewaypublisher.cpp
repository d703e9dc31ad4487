#include "gatewaypublisher.h"

#include "core/mqtt/mqttclient.h"

namespace Fatek {

GatewayPublisher::GatewayPublisher(MqttClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    m_retry.setInterval(20);
    m_retry.setSingleShot(true);
    connect(&m_retry, &QTimer::timeout, this, &GatewayPublisher::flush);
    connect(client, &MqttClient::connected, this, &GatewayPublisher::onConnected);
    connect(client, &MqttClient::disconnected, this, [this] { m_online = false; });
}

void GatewayPublisher::publishRetained(const QString &topic, const QByteArray &payload, int qos)
{
    m_qos.insert(topic, qos);
    if (m_dirty.contains(topic))
        ++m_counters.superseded;
    m_retained.insert(topic, payload);
    m_dirty.insert(topic);
    flush();
}

void GatewayPublisher::publishReply(const QString &topic, const QByteArray &payload)
{
    if (static_cast<int>(m_replies.size()) >= m_limits.maxReplies) {
        m_replies.pop_front();
        ++m_counters.repliesDropped;
    }
    m_replies.emplace_back(topic, payload);
    flush();
}

int GatewayPublisher::waiting() const
{
    return static_cast<int>(m_dirty.size()) + static_cast<int>(m_replies.size());
}

bool GatewayPublisher::hasRoom() const
{
    return !m_client->isConnected()
           || m_client->outstanding() + waiting() < m_limits.maxOutstanding;
}

void GatewayPublisher::flush()
{
    // Not before onConnected(): the client is connected a moment before its signal arrives here,
    // and what went out in that moment would go again from onConnected() (issue 33: "connecting"
    // and "up" twice at start).
    if (!m_online || !m_client->isConnected())
        return; // onConnected() sends everything
    // Replies first: someone waits for them; a retained value is only the newest state.
    while (!m_replies.empty() && m_client->outstanding() < m_limits.maxOutstanding) {
        if (!m_client->publish(m_replies.front().first, m_replies.front().second, 1, false))
            return; // the link went down meanwhile: onConnected() goes on
        m_replies.pop_front();
        ++m_counters.published;
    }
    while (!m_dirty.isEmpty() && m_client->outstanding() < m_limits.maxOutstanding) {
        const QString topic = *m_dirty.cbegin();
        if (!m_client->publish(topic, m_retained.value(topic), m_qos.value(topic, 1), true))
            return;
        m_dirty.remove(topic);
        ++m_counters.published;
    }
    if (waiting() > 0 && !m_retry.isActive())
        m_retry.start();
}

void GatewayPublisher::onConnected()
{
    m_online = true;
    // The broker may have restarted without persistence: every retained topic goes again.
    for (auto it = m_retained.cbegin(); it != m_retained.cend(); ++it)
        m_dirty.insert(it.key());
    flush();
}

} // namespace Fatek
