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

GatewayPublisher::TopicId GatewayPublisher::retainedTopic(const QString &topic, int qos)
{
    const auto found = m_topicIds.constFind(topic);
    if (found != m_topicIds.cend()) {
        m_retained[found.value()].qos = qos;
        return found.value();
    }
    const TopicId id = m_retained.size();
    m_retained.push_back({topic.toUtf8(), {}, qos, false, false});
    m_topicIds.insert(topic, id);
    return id;
}

void GatewayPublisher::publishRetained(const QString &topic, const QByteArray &payload, int qos)
{
    publishRetained(retainedTopic(topic, qos), payload);
}

void GatewayPublisher::publishRetained(TopicId topic, const QByteArray &payload)
{
    Retained &retained = m_retained[topic];
    retained.payload = payload;
    retained.set = true;
    if (retained.dirty) {
        ++m_counters.superseded;
    } else {
        retained.dirty = true;
        m_dirty.push_back(topic);
    }
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
    while (!m_dirty.empty() && m_client->outstanding() < m_limits.maxOutstanding) {
        Retained &retained = m_retained[m_dirty.front()];
        if (!m_client->publishUtf8(retained.topic, retained.payload, retained.qos, true))
            return;
        retained.dirty = false;
        m_dirty.pop_front();
        ++m_counters.published;
    }
    if (waiting() > 0 && !m_retry.isActive())
        m_retry.start();
}

void GatewayPublisher::onConnected()
{
    m_online = true;
    // The broker may have restarted without persistence: every retained topic goes again.
    for (TopicId id = 0; id < m_retained.size(); ++id) {
        Retained &retained = m_retained[id];
        if (retained.set && !retained.dirty) {
            retained.dirty = true;
            m_dirty.push_back(id);
        }
    }
    flush();
}

} // namespace Fatek
