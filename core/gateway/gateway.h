#pragma once

#include "core/protocol/message.h"
#include "gatewayconfig.h"

#include <QObject>

#include <memory>
#include <optional>
#include <vector>

namespace Fatek {

class AlarmJournalWriter;
class GatewayLink;
class HistoryWriter;

// The running gateway: one GatewayLink per connection of a configuration, and the reload of a
// new configuration (SIGHUP) that restarts only the links it changes. A link whose connection
// is unchanged keeps running: its MQTT session, its values and its status stay as they are.
// One alarm journal (AlarmJournalWriter, its own thread) for every link's alarms: their events
// are journaled, and the states it kept come back into a link's AlarmEngine before it starts.
// One history store (HistoryWriter, its own thread) for every link's recorder.
class Gateway : public QObject
{
    Q_OBJECT

public:
    explicit Gateway(QObject *parent = nullptr);
    ~Gateway() override;

    // Starts a link per connection; false (nothing left running) when one cannot start, with
    // `error` saying why. Link i of n opens i/n of the shortest poll interval after the first.
    bool start(const GatewayConfig &config, QString *connection, Message *error);
    // Applies `config`: links of connections that were removed or changed stop, and the new or
    // changed ones start once their old link has stopped (a restarted link keeps its MQTT client
    // id: two at once would throw each other off the broker). A change of the broker, the
    // prefix, read-only, discovery, the alarm journal or the history restarts every link.
    void reload(const GatewayConfig &config);
    // Every link publishes offline and disconnects; stopped() when all have.
    void stop();

Q_SIGNALS:
    // One log line's worth; `connection` names the link it is about.
    void logEvent(const QString &connection, const Fatek::Message &event);
    void stopped();
    // A reload is done: every link of the new configuration runs (or failed to start: logged).
    void reloaded();

private:
    struct Running
    {
        GatewayConnectionConfig config;
        std::unique_ptr<GatewayLink> link;
        bool retiring = false; // stopping for a reload: removed when stopped
    };

    bool startLink(const GatewayConnectionConfig &connection, int pollDelayMs, Message *error);
    // Opens the configuration's alarm journal when some connection has alarms (and the journal
    // is not the one open already).
    void openJournal();
    // Opens the configuration's history store when some item is recorded (and the store is not
    // the one open already, with the same retention).
    void openHistory();
    void onLinkStopped();
    void startWaiting();

    GatewayConfig m_config;
    AlarmJournalWriter *m_journal = nullptr; // a child; none while no connection has alarms
    QString m_journalPath;
    HistoryWriter *m_history = nullptr; // a child; none while nothing is recorded
    GatewayConfig::History m_historyConfig;
    std::vector<HistoryWriter *> m_retiredHistory; // children, until their links are gone
    std::vector<Running> m_links;
    // Connections of a reload waiting for their old link to stop before they start.
    QList<GatewayConnectionConfig> m_waiting;
    bool m_reloading = false;
    // A configuration given while a reload was under way: applied when it is done.
    std::optional<GatewayConfig> m_next;
    bool m_stopping = false;
};

} // namespace Fatek
