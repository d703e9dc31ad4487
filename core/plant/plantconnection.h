#pragma once

#include "core/link/gatewaywatchsettings.h"
#include "core/link/plclink.h"
#include "core/transport/linksettings.h"
#include "plantconsumer.h"

#include <QDeadlineTimer>
#include <QHash>
#include <QList>
#include <QObject>
#include <QSet>

#include <vector>

namespace Fatek {

// One connection of the plant: a PlcLink (a direct session, or a gateway watched through a
// broker) and the consumers of its items. The one place where the item sets of every consumer are
// merged into the link's single list and where the link's values are handed out, each consumer
// getting its own items' values. The studio's tables and the gateway's MQTT side are consumers
// alike; adding one (alarms, history, a server) touches no other. Lives in the link's thread.
class PlantConnection : public QObject
{
    Q_OBJECT

public:
    // How a direct link is made.
    struct DirectOptions
    {
        bool readOnly = false;
        // Whether the session keeps its traffic log (the studio's raw console reads it; a
        // gateway's link has no reader for it: 10,000 frames per link for nothing).
        bool trafficLog = true;
    };

    // Takes `link` (its parent becomes this connection).
    explicit PlantConnection(PlcLink *link, QObject *parent = nullptr);
    // The kinds of link, made here: a direct session on a serial, TCP or UDP line; a gateway's
    // connection watched through its broker.
    static PlantConnection *direct(const LinkSettings &settings, const DirectOptions &options,
                                   QObject *parent = nullptr);
    static PlantConnection *throughGateway(const GatewayWatchSettings &settings,
                                           QObject *parent = nullptr);
    ~PlantConnection() override;

    PlcLink *link() const { return m_link; }

    void open();
    void close(CloseMode mode = CloseMode::Drain);
    void reconnectNow();
    LinkState linkState() const { return m_state; }
    Message linkReason() const { return m_reason; }
    // Connection attempts that failed and open links that broke (refused port, cable pulled).
    quint64 linkFailures() const { return m_linkFailures; }
    // Whether the link ever came up since it was made.
    bool hasConnected() const { return m_hasConnected; }
    // The link's counters: a direct link's session as of now, else the last it reported.
    SessionStatistics statistics() const;

    // Replaces what `consumer` watches (an empty list removes it). Keys are unique in the process
    // (WatchedItem::newKey()); a consumer's values start with the link's next report.
    void subscribe(PlantConsumer *consumer, const QList<WatchedItem> &items);
    void unsubscribe(PlantConsumer *consumer);
    int consumerCount() const { return static_cast<int>(m_consumers.size()); }
    // Every item watched, of every consumer.
    int itemCount() const;
    // The stations some consumer watches an item of.
    QSet<quint8> watchedStations() const { return m_stations; }

    // Operator mode, enforced by the link.
    void setReadOnly(bool readOnly) { m_link->setReadOnly(readOnly); }
    bool isReadOnly() const { return m_link->isReadOnly(); }
    // Writes through the link (PlcLink::write): one result type for every front end.
    void write(const WatchItemSpec &item, std::uint64_t raw, QObject *context,
               PlcLink::WriteCompletion completion);
    void write(const WatchItemSpec &item, std::uint64_t raw, const QDeadlineTimer &deadline,
               QObject *context, PlcLink::WriteCompletion completion);
    int pendingWrites() const { return m_link->pendingWrites(); }
    int closeDrainMs() const { return m_link->closeDrainMs(); }

Q_SIGNALS:
    void linkStateChanged(Fatek::LinkState state, const Fatek::Message &reason);
    // Every batch the link reported, before it is handed to the consumers (counters, activity).
    void valuesArrived(const QList<Fatek::WatchItemValue> &values);
    void statisticsChanged(const Fatek::SessionStatistics &statistics);

private:
    struct Consumer
    {
        PlantConsumer *consumer = nullptr;
        QList<WatchedItem> items;
    };

    void onValues(const QList<WatchItemValue> &values);
    void onLinkState(LinkState state, const Message &reason);
    void pushItems();
    // Whether `consumer` is still subscribed (a consumer may leave while values are handed out).
    bool isSubscribed(const PlantConsumer *consumer) const;

    PlcLink *m_link;
    std::vector<Consumer> m_consumers; // in subscription order
    // Item key -> its consumer, while there are several (one consumer owns every value).
    QHash<std::uint64_t, PlantConsumer *> m_owner;
    QSet<quint8> m_stations; // of every consumer's items
    LinkState m_state = LinkState::Closed;
    Message m_reason;
    quint64 m_linkFailures = 0;
    bool m_hasConnected = false;
    SessionStatistics m_statistics;
};

} // namespace Fatek
