#pragma once

#include "commandage.h"
#include "core/mqtt/gatewaypayload.h"
#include "core/watch/watchlist.h"
#include "gatewayconfig.h"

#include <QDateTime>
#include <QHash>
#include <QObject>
#include <QString>

#include <functional>

namespace Fatek {

class GatewayPublisher;
class MqttClient;
class PlantConnection;

// The write commands of one gateway connection: takes <prefix>/<conn>/<station>/<address>/set
// messages from the broker, checks them (topic, size, retained, read-only, age, allowlist,
// format, value, room) and writes what passes through the plant connection; every command is
// answered once on its reply topic (twice when its outcome is first unknown) and logged.
class GatewayCommands : public QObject
{
    Q_OBJECT

public:
    // Writes waiting for the PLC link at most; more are refused (a peer flooding /set topics).
    static constexpr int MaxPendingWrites = 100;
    // Longest /set payload taken.
    static constexpr int MaxCommandBytes = 4096;
    // How far a command's "time" may lie ahead of the gateway's clock (CommandAge).
    static constexpr int MaxAheadSec = CommandAge::MaxAheadSec;
    // Set topics whose last command is remembered (to know the broker's retained copy of one
    // already answered); beyond it the memory starts again.
    static constexpr int MaxRememberedCommands = 256;

    struct Counters
    {
        quint64 accepted = 0; // handed to the PLC link
        quint64 refused = 0;  // refused by the gateway (read-only, allowlist, value)
        quint64 failed = 0;   // accepted and not carried out (refused by the PLC, read back)
        quint64 unknown = 0;  // accepted, outcome still unknown after the read-back
    };

    // The watched item at an item topic, if any (a command's format and allowNonFinite default
    // to its item's).
    using WatchedAt = std::function<const WatchItemSpec *(const QString &topic)>;

    GatewayCommands(const GatewayConnectionConfig &config, const QString &prefix, bool readOnly,
                    WatchedAt watched, MqttClient *client, GatewayPublisher *publisher,
                    PlantConnection *plant, QObject *parent = nullptr);

    // Commands that arrive from now on are ignored (the connection is stopping).
    void stop() { m_stopping = true; }
    Counters counters() const { return m_counters; }

Q_SIGNALS:
    // Every write accepted or refused, and set topics that name no item.
    void logEvent(const Fatek::Message &event);

private:
    void onCommand(const QString &topic, const QByteArray &payload, bool retained, bool queued);
    // Answers a set topic that names no item of this connection (or nowhere, if it is no set
    // topic of it); true when it was one.
    bool refuseBadTopic(const QString &topic);
    // Why a command is too old to carry out (empty: it is not).
    Message tooOld(const GatewayPayload::SetCommand &command, bool queued) const;
    // How old the command is: by its own time, and by the broker's outage when it was kept there.
    qint64 commandAgeMs(const GatewayPayload::SetCommand &command, bool queued) const;
    // The item a command writes: its format, else the watched item's, else the address's default.
    WatchItemSpec specOf(int station, const Address &address,
                         const GatewayPayload::SetCommand &command) const;
    void write(const GatewayPayload::Reply &reply, const ItemValues &item, std::uint64_t raw,
               qint64 remainingMs);
    void refuse(GatewayPayload::Reply reply, const Message &why);
    void answer(const GatewayPayload::Reply &reply);

    GatewayConnectionConfig m_config;
    QString m_prefix;
    bool m_readOnly;
    WatchedAt m_watched;
    GatewayPublisher *m_publisher;
    PlantConnection *m_plant;
    Counters m_counters;
    int m_pendingWrites = 0;
    bool m_stopping = false;
    bool m_brokerDown = true;
    QDateTime m_brokerDownAt; // when the link to the broker last went down (invalid: never)
    // The last command per set topic (payload), for onCommand's retained copies.
    QHash<QString, QByteArray> m_lastCommand;
};

} // namespace Fatek
