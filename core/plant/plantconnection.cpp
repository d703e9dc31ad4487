#include "plantconnection.h"

#include "core/link/gatewaywatch.h"
#include "core/link/sessionlink.h"
#include "core/session/session.h"

#include <algorithm>

namespace Fatek {

PlantConnection::PlantConnection(PlcLink *link, QObject *parent)
    : QObject(parent)
    , m_link(link)
{
    m_link->setParent(this);
    m_state = m_link->linkState();
    connect(m_link, &PlcLink::linkStateChanged, this, &PlantConnection::onLinkState);
    connect(m_link, &PlcLink::itemValues, this, &PlantConnection::onValues);
    connect(m_link, &PlcLink::statisticsChanged, this, [this](const SessionStatistics &statistics) {
        m_statistics = statistics;
        Q_EMIT statisticsChanged(statistics);
    });
}

PlantConnection *PlantConnection::direct(const LinkSettings &settings, const DirectOptions &options,
                                         QObject *parent)
{
    auto *link = new SessionLink(settings);
    if (!options.trafficLog)
        link->dropTrafficLog();
    link->setReadOnly(options.readOnly);
    return new PlantConnection(link, parent);
}

PlantConnection *PlantConnection::throughGateway(const GatewayWatchSettings &settings,
                                                 QObject *parent)
{
    return new PlantConnection(new GatewayWatch(settings), parent);
}

PlantConnection::~PlantConnection()
{
    // The link's destructor stops its thread; nothing may arrive in a half-destroyed object.
    disconnect(m_link, nullptr, this, nullptr);
}

void PlantConnection::open()
{
    m_link->open();
}

void PlantConnection::close(CloseMode mode)
{
    m_link->close(mode);
}

void PlantConnection::reconnectNow()
{
    m_link->reconnectNow();
}

SessionStatistics PlantConnection::statistics() const
{
    if (const Session *session = m_link->session())
        return session->statistics();
    return m_statistics;
}

void PlantConnection::subscribe(PlantConsumer *consumer, const QList<WatchedItem> &items)
{
    if (items.isEmpty()) {
        unsubscribe(consumer);
        return;
    }
    const auto it = std::find_if(m_consumers.begin(), m_consumers.end(),
                                 [consumer](const Consumer &c) { return c.consumer == consumer; });
    if (it != m_consumers.end())
        it->items = items;
    else
        m_consumers.push_back({consumer, items});
    pushItems();
}

void PlantConnection::unsubscribe(PlantConsumer *consumer)
{
    const auto it = std::find_if(m_consumers.begin(), m_consumers.end(),
                                 [consumer](const Consumer &c) { return c.consumer == consumer; });
    if (it == m_consumers.end())
        return;
    m_consumers.erase(it);
    pushItems();
}

bool PlantConnection::isSubscribed(const PlantConsumer *consumer) const
{
    return std::any_of(m_consumers.cbegin(), m_consumers.cend(),
                       [consumer](const Consumer &c) { return c.consumer == consumer; });
}

int PlantConnection::itemCount() const
{
    qsizetype count = 0;
    for (const Consumer &c : m_consumers)
        count += c.items.size();
    return static_cast<int>(count);
}

void PlantConnection::pushItems()
{
    // A link has a single list of items: the union of every consumer's. With one consumer it is
    // that consumer's list itself (shared, not copied: a gateway link holds thousands).
    m_owner.clear();
    // Asked at every statistics report (the Connections dock's silent stations): kept, not
    // counted again over thousands of items each time.
    m_stations.clear();
    for (const Consumer &c : m_consumers) {
        for (const WatchedItem &item : c.items)
            m_stations.insert(item.spec.station);
    }
    if (m_consumers.size() == 1) {
        m_link->setItems(m_consumers.front().items);
        return;
    }
    QList<WatchedItem> all;
    for (const Consumer &c : m_consumers) {
        all += c.items;
        for (const WatchedItem &item : c.items)
            m_owner.insert(item.key, c.consumer);
    }
    m_link->setItems(all);
}

void PlantConnection::write(const WatchItemSpec &item, std::uint64_t raw, QObject *context,
                            PlcLink::WriteCompletion completion)
{
    m_link->write(item, raw, context, std::move(completion));
}

void PlantConnection::write(const WatchItemSpec &item, std::uint64_t raw,
                            const QDeadlineTimer &deadline, QObject *context,
                            PlcLink::WriteCompletion completion)
{
    m_link->write(item, raw, deadline, context, std::move(completion));
}

void PlantConnection::onValues(const QList<WatchItemValue> &values)
{
    Q_EMIT valuesArrived(values);
    if (m_consumers.size() == 1) {
        // One consumer (a gateway's MQTT side, a studio with one table): a link reports only the
        // items of its last setItems() (PlcLink), here all of them this consumer's.
        m_consumers.front().consumer->plantValues(values);
        return;
    }
    // Each consumer gets its own items' values, in the batch's order; values of no consumer's
    // item (one just removed) go nowhere.
    std::vector<std::pair<PlantConsumer *, QList<WatchItemValue>>> split;
    for (const WatchItemValue &v : values) {
        PlantConsumer *owner = m_owner.value(v.key);
        if (!owner)
            continue;
        auto it = std::find_if(split.begin(), split.end(),
                               [owner](const auto &entry) { return entry.first == owner; });
        if (it == split.end())
            it = split.insert(split.end(), {owner, {}});
        it->second.append(v);
    }
    for (const auto &[consumer, own] : split) {
        if (isSubscribed(consumer)) // not if an earlier consumer's call removed it
            consumer->plantValues(own);
    }
}

void PlantConnection::onLinkState(LinkState state, const Message &reason)
{
    // Every failed attempt and every broken link passes through Lost once; a link without a
    // session of its own stays Lost while it retries, and says so again only when the reason
    // changes.
    if (state == LinkState::Lost && (m_link->session() || m_state != LinkState::Lost))
        ++m_linkFailures;
    if (state == LinkState::Connected)
        m_hasConnected = true;
    m_state = state;
    m_reason = reason;
    // A copy: a consumer may unsubscribe (or another subscribe) from inside its call.
    std::vector<PlantConsumer *> consumers;
    for (const Consumer &c : m_consumers)
        consumers.push_back(c.consumer);
    for (PlantConsumer *consumer : consumers) {
        if (isSubscribed(consumer))
            consumer->plantLinkState(state, reason);
    }
    Q_EMIT linkStateChanged(state, reason);
}

} // namespace Fatek
