#include "gateway.h"

#include "alarmnorth.h"
#include "core/alarm/alarmengine.h"
#include "core/alarm/alarmjournalwriter.h"
#include "core/history/historywriter.h"
#include "core/qtbridge/secrets.h"
#include "gatewaylink.h"
#include "gatewaymessages.h"
#include "homeassistantdiscovery.h"

#include <QSet>

#include <algorithm>
#include <utility>

namespace Fatek {

namespace {

std::vector<HomeAssistantDiscovery::Entry> discoveryOf(const GatewayConfig &config,
                                                       const GatewayConnectionConfig &connection)
{
    return HomeAssistantDiscovery::entries(config.homeAssistant.prefix, config.prefix, connection,
                                           config.readOnly);
}

} // namespace

Gateway::Gateway(QObject *parent)
    : QObject(parent)
{}

Gateway::~Gateway() = default;

bool Gateway::start(const GatewayConfig &config, QString *connection, Message *error)
{
    m_config = config;
    openJournal();
    openHistory();
    // Link i of n opens i/n of the shortest interval (at most 1 s) after the first, so that their
    // poll cycles, and the bursts of publications they cause, are spread over the interval.
    int shortestMs = 1000;
    for (const GatewayConnectionConfig &c : config.connections) {
        for (const WatchTableSpec &table : c.tables)
            shortestMs = std::min(shortestMs, table.intervalMs);
    }
    const auto linkCount = static_cast<int>(config.connections.size());
    for (const GatewayConnectionConfig &c : config.connections) {
        const int pollDelayMs = static_cast<int>(m_links.size()) * shortestMs / linkCount;
        if (!startLink(c, pollDelayMs, error)) {
            *connection = c.name;
            m_links.clear();
            return false;
        }
    }
    return true;
}

void Gateway::openJournal()
{
    if (m_config.alarmCount() == 0 || (m_journal && m_journalPath == m_config.alarmJournal))
        return;
    // Another file (a reload changed it): every link restarts and attaches to the new one.
    delete m_journal;
    m_journalPath = m_config.alarmJournal;
    m_journal = new AlarmJournalWriter(m_journalPath, this);
    connect(m_journal, &AlarmJournalWriter::failed, this, [this](const Message &error) {
        Q_EMIT logEvent(QStringLiteral("fatek-gateway"), msg<MsgId::GatewayLogAlarmJournal>(error));
    });
}

void Gateway::openHistory()
{
    if (m_config.historyCount() == 0
        || (m_history && m_historyConfig.store == m_config.history.store
            && m_historyConfig.retention == m_config.history.retention))
        return;
    // Links restart (the history's change restarts every link) and record into the new one; the
    // old store stays until the links recording into it are gone (each keeps an Off sample as it
    // goes).
    if (m_history)
        m_retiredHistory.push_back(m_history);
    m_historyConfig = m_config.history;
    m_history = new HistoryWriter(m_historyConfig.store, m_historyConfig.retention, this);
    connect(m_history, &HistoryWriter::failed, this, [this](const Message &error) {
        Q_EMIT logEvent(QStringLiteral("fatek-gateway"), msg<MsgId::GatewayLogHistory>(error));
    });
    connect(m_history, &HistoryWriter::recovered, this, [this] {
        Q_EMIT logEvent(QStringLiteral("fatek-gateway"),
                        msg<MsgId::GatewayLogHistoryRecovered>(
                            Secrets::maskUrl(m_history->location()).toStdString()));
    });
}

bool Gateway::startLink(const GatewayConnectionConfig &connection, int pollDelayMs, Message *error)
{
    auto link = std::make_unique<GatewayLink>(connection, m_config.prefix, m_config.broker,
                                              m_config.readOnly);
    if (m_config.homeAssistant.discovery)
        link->setDiscovery(discoveryOf(m_config, connection));
    // Before start: the kept states are published with the link's first publications.
    if (m_journal && link->alarms()->alarmCount() > 0) {
        m_journal->attach(link->alarms());
        link->awaitAlarmRestore();
    }
    if (m_history && connection.historyCount(m_config.history.recordAll.has_value()) > 0)
        link->setHistory(m_history, m_config.history.recordAll);
    const QString name = connection.name;
    connect(link.get(), &GatewayLink::logEvent, this,
            [this, name](const Message &event) { Q_EMIT logEvent(name, event); });
    if (!link->start(error, pollDelayMs))
        return false;
    Q_EMIT logEvent(name, msg<MsgId::GatewayLogStarted>(connection.itemCount(),
                                                        connection.link.toString().toStdString(),
                                                        m_config.broker.toUrl().toStdString()));
    // Queued: the link is deleted here, never inside its own signal.
    connect(link.get(), &GatewayLink::stopped, this, &Gateway::onLinkStopped, Qt::QueuedConnection);
    m_links.push_back({connection, std::move(link), false});
    return true;
}

void Gateway::reload(const GatewayConfig &config)
{
    if (m_stopping)
        return;
    if (m_reloading) {
        m_next = config;
        return;
    }
    const bool everything
        = config.broker != m_config.broker || config.prefix != m_config.prefix
          || config.readOnly != m_config.readOnly || config.homeAssistant != m_config.homeAssistant
          || config.alarmJournal != m_config.alarmJournal || config.history != m_config.history;
    // Discovery configs that stay: a retiring link clears the others (entities removed).
    QSet<QString> keep;
    if (config.homeAssistant.discovery) {
        for (const GatewayConnectionConfig &c : config.connections) {
            for (const HomeAssistantDiscovery::Entry &entry : discoveryOf(config, c))
                keep.insert(entry.topic);
        }
    }
    // Alarm states that stay: a retiring link clears the others (alarms removed).
    QSet<QString> keepAlarms;
    for (const GatewayConnectionConfig &c : config.connections)
        keepAlarms.unite(AlarmNorth::stateTopics(config.prefix, c));
    m_config = config;
    openJournal();
    openHistory();
    m_reloading = true;
    m_waiting.clear();
    for (Running &running : m_links) {
        const auto same = std::find_if(
            config.connections.cbegin(), config.connections.cend(),
            [&running](const GatewayConnectionConfig &c) { return c.name == running.config.name; });
        if (!everything && same != config.connections.cend() && *same == running.config)
            continue; // unchanged: keeps running untouched
        running.retiring = true;
    }
    for (const GatewayConnectionConfig &c : config.connections) {
        const bool kept = std::any_of(m_links.cbegin(), m_links.cend(), [&c](const Running &r) {
            return !r.retiring && r.config.name == c.name;
        });
        if (!kept)
            m_waiting.append(c);
    }
    for (Running &running : m_links) {
        if (!running.retiring)
            continue;
        running.link->clearDiscovery(keep);
        running.link->clearAlarms(keepAlarms);
        running.link->stop();
    }
    startWaiting();
}

void Gateway::onLinkStopped()
{
    // Links stopped for a reload go; when stopping, all of them.
    const auto gone = std::remove_if(m_links.begin(), m_links.end(), [this](const Running &r) {
        return r.link->isStopped() && (r.retiring || m_stopping);
    });
    m_links.erase(gone, m_links.end());
    if (std::none_of(m_links.cbegin(), m_links.cend(),
                     [](const Running &r) { return r.retiring; })) {
        qDeleteAll(m_retiredHistory);
        m_retiredHistory.clear();
    }
    if (m_stopping) {
        if (m_links.empty())
            Q_EMIT stopped();
        return;
    }
    startWaiting();
}

void Gateway::startWaiting()
{
    if (!m_reloading)
        return;
    for (auto it = m_waiting.begin(); it != m_waiting.end();) {
        const QString &name = it->name;
        const bool oldRunning
            = std::any_of(m_links.cbegin(), m_links.cend(),
                          [&name](const Running &r) { return r.config.name == name; });
        if (oldRunning) {
            ++it;
            continue;
        }
        Message error;
        if (!startLink(*it, 0, &error))
            Q_EMIT logEvent(name, error);
        it = m_waiting.erase(it);
    }
    if (m_waiting.isEmpty() && std::none_of(m_links.cbegin(), m_links.cend(), [](const Running &r) {
            return r.retiring;
        })) {
        m_reloading = false;
        Q_EMIT reloaded();
        if (m_next) {
            const GatewayConfig next = *std::exchange(m_next, std::nullopt);
            reload(next);
        }
    }
}

void Gateway::stop()
{
    if (m_stopping)
        return;
    m_stopping = true;
    m_waiting.clear();
    if (m_links.empty()) {
        Q_EMIT stopped();
        return;
    }
    for (Running &running : m_links)
        running.link->stop();
}

} // namespace Fatek
