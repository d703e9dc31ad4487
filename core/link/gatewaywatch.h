#pragma once

#include "core/mqtt/gatewaypayload.h"
#include "gatewaywatchsettings.h"
#include "plclink.h"

#include <QHash>
#include <QList>
#include <QPointer>
#include <QString>
#include <QTimer>

#include <optional>
#include <vector>

namespace Fatek {

class MqttClient;

// A connection of fatek-gateway watched through the broker: a PlcLink whose items are the
// gateway's. Each watched item takes the payload the gateway publishes for its station and
// address as it is (the payload carries every element's word); the item is stale while the
// gateway or the broker is away, and not published when the gateway has no item there (or one
// with fewer elements). Writes go as commands with the raw words and the format on the item's /set
// topic, completed by the gateway's /reply.
class GatewayWatch : public PlcLink
{
    Q_OBJECT

public:
    explicit GatewayWatch(const GatewayWatchSettings &settings, QObject *parent = nullptr);
    ~GatewayWatch() override;

    GatewayWatchSettings settings() const { return m_settings; }

    Kind kind() const override { return Kind::Gateway; }
    // Connects to the broker (reconnecting with its backoff) and subscribes; close() disconnects.
    void open() override;
    // Unanswered writes end at once (nobody will read their replies), whatever the mode.
    void close(CloseMode mode = CloseMode::Drain) override;
    // The broker client waits out its backoff; a new start skips it.
    void reconnectNow() override;

    // Connected: the broker link is up and the gateway says its PLC link is up. Connecting: the
    // broker or the gateway's status is not there yet, or the gateway connects to its PLCs.
    // Lost: the broker link broke, or the gateway is offline or lost its PLCs (reason says which).
    LinkState linkState() const override { return m_state; }
    Message linkReason() const { return m_reason; }
    // What the gateway says its link is ("TCP 10.0.0.7:500, FACON"); empty before its status.
    QString peerText() const override { return m_gatewayLink; }

    // The gateway polls at the intervals of its configuration: the items' are not used.
    void setItems(const QList<WatchedItem> &items) override;
    bool takesIntervals() const override { return false; }

    void setReadOnly(bool readOnly) override { m_readOnly = readOnly; }
    bool isReadOnly() const override { return m_readOnly; }
    // A command is gone once published: a close has nothing to wait for.
    int pendingWrites() const override { return 0; }
    int closeDrainMs() const override { return 0; }
    // Commands published and not answered yet.
    int unansweredWrites() const { return static_cast<int>(m_writes.size()); }

    // How long a write waits for the gateway's reply [5000 ms].
    void setReplyTimeoutMs(int ms) { m_replyTimeoutMs = ms; }
    int replyTimeoutMs() const { return m_replyTimeoutMs; }
    // How long after the gateway's status says up its items may take before an item that has
    // none is reported as not published [1000 ms].
    void setPublishedGraceMs(int ms) { m_graceMs = ms; }

protected:
    // Publishes a command with the item's words for `raw` and its format; the completion gets the
    // gateway's reply, or why not (read-only, not connected, no reply within replyTimeoutMs()).
    // The deadline is not used: the gateway refuses a command older than its own age limit (the
    // command carries its time).
    void writeItem(const WatchItemSpec &item, std::uint64_t raw,
                   const std::optional<QDeadlineTimer> &deadline, QObject *context,
                   WriteCompletion completion) override;

private:
    struct Published
    {
        std::vector<std::uint32_t> words;
        ValueQuality quality = ValueQuality::Error;
        QDateTime time;
        Message error;
        QString name;
    };
    struct Watched
    {
        WatchedItem item;
        ItemValues values;
        QString key; // "station/address" of its payload
    };
    struct PendingWrite
    {
        QPointer<QObject> context;
        bool hasContext = false;
        WriteCompletion completion;
        std::string what;      // "R100 (station 1) = 12.5", for a refusal's message
        bool reported = false; // an unknown outcome was reported (not final)
    };

    void onConnected();
    void onDisconnected(const Message &reason);
    void onMessage(const QString &topic, const QByteArray &payload);
    void onItem(int station, const Address &address, const QByteArray &payload);
    void onStatus(const QByteArray &payload);
    void onReply(const QByteArray &payload);
    void setState(LinkState state, const Message &reason);
    void markDirty(const QString &key);
    void markAllDirty();
    void flush();
    WatchItemValue valueOf(const Watched &watched) const;
    void finishWrite(const QString &id, const LinkWriteResult &result);
    static QString keyOf(int station, const Address &address);

    GatewayWatchSettings m_settings;
    MqttClient *m_client;
    LinkState m_state = LinkState::Closed;
    Message m_reason;
    QString m_gatewayLink;
    bool m_brokerUp = false;
    std::optional<GatewayPayload::Status> m_status;
    bool m_readOnly = false;
    int m_replyTimeoutMs = 5000;
    int m_graceMs = 1000;
    // False from a broker (re)connection until the grace after the gateway's first "up": a
    // missing item may still be coming.
    bool m_settled = false;
    QTimer m_graceTimer;
    QTimer m_flushTimer;
    // "station/address" → the gateway's latest payload for the item there.
    QHash<QString, Published> m_published;
    std::vector<Watched> m_items;
    // "station/address" → indexes into m_items.
    QHash<QString, QList<int>> m_itemsAt;
    QList<int> m_dirty;
    bool m_allDirty = false;
    QHash<QString, PendingWrite> m_writes;
};

} // namespace Fatek
