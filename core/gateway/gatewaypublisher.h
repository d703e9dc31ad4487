#pragma once

#include <QByteArray>
#include <QHash>
#include <QObject>
#include <QString>
#include <QTimer>

#include <deque>
#include <utility>
#include <vector>

namespace Fatek {

class MqttClient;

// What the gateway sends to one broker connection, bounded however long the broker is away or
// slow. Retained topics (items, status, statistics) keep only their latest payload: one waiting
// to go that is replaced counts as superseded, and every retained topic is sent again after each
// (re)connect (a broker without persistence forgot them). Replies are queued, at most
// maxReplies; the oldest is dropped (and counted) beyond that. While the client has more than
// maxOutstanding messages not yet written, nothing more is handed to it: the rest waits here.
class GatewayPublisher : public QObject
{
    Q_OBJECT

public:
    struct Limits
    {
        int maxOutstanding = 1000;
        int maxReplies = 1000;
    };
    struct Counters
    {
        quint64 published = 0;      // messages handed to the broker connection
        quint64 superseded = 0;     // retained payloads replaced before they went out
        quint64 repliesDropped = 0; // replies dropped because maxReplies were waiting
    };

    // A retained topic, named once: publishRetained(TopicId, ...) needs no look-up or conversion
    // of the topic per message (an item's topic, published on every change).
    using TopicId = std::size_t;

    explicit GatewayPublisher(MqttClient *client, QObject *parent = nullptr);

    void setLimits(const Limits &limits) { m_limits = limits; }
    // The id of a retained topic (the same for the same topic), sent with `qos`.
    TopicId retainedTopic(const QString &topic, int qos = 1);
    // The topic's new retained state. Item values go with QoS 0: a newer value supersedes a lost
    // one, every topic is sent again after a reconnect, and QoS 1's acknowledgements would double
    // the broker's work at plant rates (docs/performance.md). Status and statistics keep QoS 1.
    void publishRetained(const QString &topic, const QByteArray &payload, int qos = 1);
    void publishRetained(TopicId topic, const QByteArray &payload);
    // An answer to a command (QoS 1, not retained).
    void publishReply(const QString &topic, const QByteArray &payload);
    // Messages waiting here (retained topics not yet sent, replies).
    int waiting() const;
    // Whether more may be handed over now (or kept as the latest state while the broker is away):
    // false while what waits here and in the client reaches maxOutstanding.
    bool hasRoom() const;
    Counters counters() const { return m_counters; }
    // Hands over what may go now.
    void flush();

private:
    void onConnected();

    struct Retained
    {
        QByteArray topic; // UTF-8
        QByteArray payload;
        int qos = 1;
        bool set = false;   // published at least once
        bool dirty = false; // not sent since it changed (in m_dirty)
    };

    MqttClient *m_client;
    Limits m_limits;
    Counters m_counters;
    std::vector<Retained> m_retained; // every retained topic's latest payload, by TopicId
    QHash<QString, TopicId> m_topicIds;
    std::deque<TopicId> m_dirty; // retained topics not sent since they changed, oldest first
    std::deque<std::pair<QString, QByteArray>> m_replies;
    QTimer m_retry;        // flush again while held back by the outstanding bound
    bool m_online = false; // onConnected() ran for the client's present connection
};

} // namespace Fatek
