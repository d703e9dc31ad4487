#pragma once

#include "core/session/sessiontypes.h"
#include "core/session/watchvalue.h"
#include "core/watch/valueformat.h"
#include "gatewaypayload.h"
#include "mqttbrokersettings.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QTimer>

#include <functional>
#include <optional>

namespace Fatek {

class MqttClient;

// Where a gateway publishes one of its connections: the broker, the topic prefix and the
// gateway's connection name (GatewayTopics).
struct GatewayWatchSettings
{
    MqttBrokerSettings broker;
    QString prefix = QStringLiteral("fatek");
    QString connection;

    // Empty when usable, else what to fix (the broker's settings, the prefix, the name).
    Message validate() const;
    bool operator==(const GatewayWatchSettings &) const = default;
};

// Watches one gateway connection through the broker, the way a Session watches a PLC link: the
// one place that turns the gateway's item payloads into element values. Keeps the latest words
// of every published item (element n of an item is its address advanced by n), serves a watch
// list with them, marks them stale while the gateway or the broker is away, and sends writes as
// commands on the item's /set topic, completed by the gateway's /reply.
class GatewayWatch : public QObject
{
    Q_OBJECT

public:
    using WriteCompletion = std::function<void(const GatewayPayload::Reply &reply)>;

    explicit GatewayWatch(const GatewayWatchSettings &settings, QObject *parent = nullptr);
    ~GatewayWatch() override;

    GatewayWatchSettings settings() const { return m_settings; }

    // Connects to the broker (reconnecting with its backoff) and subscribes; close() disconnects.
    void open();
    void close();

    // Connected: the broker link is up and the gateway says its PLC link is up. Connecting: the
    // broker or the gateway's status is not there yet, or the gateway connects to its PLCs.
    // Lost: the broker link broke, or the gateway is offline or lost its PLCs (reason says which).
    LinkState linkState() const { return m_state; }
    Message linkReason() const { return m_reason; }
    // What the gateway says its link is ("TCP 10.0.0.7:500, FACON"); empty before its status.
    QString gatewayLink() const { return m_gatewayLink; }

    // Replaces the watched elements; values() reports them as the gateway publishes (intervals
    // are the gateway's, not the entries').
    void setWatchList(const QList<WatchEntry> &entries);

    // Operator mode: write() refuses before anything is published.
    void setReadOnly(bool readOnly) { m_readOnly = readOnly; }
    bool isReadOnly() const { return m_readOnly; }
    // How long a write waits for the gateway's reply [5000 ms].
    void setReplyTimeoutMs(int ms) { m_replyTimeoutMs = ms; }
    int replyTimeoutMs() const { return m_replyTimeoutMs; }
    // How long after the gateway's status says up its items may take before an entry that has
    // none is reported as not published [1000 ms].
    void setPublishedGraceMs(int ms) { m_graceMs = ms; }

    // Publishes `text` (in `format`) as a command for the item at `address`; `completion` is called
    // once on `context`'s thread with the gateway's reply, or with ok false and why (read-only,
    // not connected, no reply within replyTimeoutMs()); dropped when `context` is destroyed.
    void write(int station, const Address &address, const QString &text, DisplayFormat format,
               bool swapWords, QObject *context, WriteCompletion completion);
    // Writes published and not answered yet.
    int pendingWrites() const { return static_cast<int>(m_writes.size()); }

Q_SIGNALS:
    void linkStateChanged(Fatek::LinkState state, const Fatek::Message &reason);
    // The entries whose values changed since the last batch (coalesced).
    void values(const QList<Fatek::WatchValue> &values);

private:
    struct Element
    {
        std::uint32_t value = 0;
        ValueQuality quality = ValueQuality::Error;
        QDateTime time;
        Message error;
    };
    struct PendingWrite
    {
        QPointer<QObject> context;
        bool hasContext = false;
        WriteCompletion completion;
        GatewayPayload::Reply request; // station, address and value, for a timeout's answer
    };

    void onConnected();
    void onDisconnected(const Message &reason);
    void onMessage(const QString &topic, const QByteArray &payload);
    void onItem(const QString &topic, const QByteArray &payload);
    void onStatus(const QByteArray &payload);
    void onReply(const QByteArray &payload);
    void setState(LinkState state, const Message &reason);
    void markDirty(const QString &elementKey);
    void markAllDirty();
    void flush();
    WatchValue valueOf(const WatchEntry &entry) const;
    void finishWrite(const QString &id, const GatewayPayload::Reply &reply);
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
    // "station/address" → the latest value of that element.
    QHash<QString, Element> m_elements;
    // Item topic → the element keys its last payload covered (an item's payload replaced or
    // removed takes its elements with it).
    QHash<QString, QStringList> m_itemElements;
    QList<WatchEntry> m_entries;
    // Element key → indexes into m_entries.
    QHash<QString, QList<int>> m_entriesOf;
    QList<int> m_dirty;
    bool m_allDirty = false;
    QHash<QString, PendingWrite> m_writes;
    quint64 m_nextWrite = 1;
};

} // namespace Fatek
