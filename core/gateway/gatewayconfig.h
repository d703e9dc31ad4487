#pragma once

#include "core/history/historytypes.h"
#include "core/mqtt/mqttbrokersettings.h"
#include "core/protocol/addressrange.h"
#include "core/protocol/result.h"
#include "core/transport/linksettings.h"
#include "core/watch/historysetting.h"
#include "core/watch/watchlist.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <optional>
#include <vector>

namespace Fatek {

// One PLC link of the gateway: where the PLC is, what to publish, what may be written.
struct GatewayConnectionConfig
{
    struct WatchListFileRef
    {
        QString file;                  // as written in the configuration
        std::optional<int> intervalMs; // overrides every table's interval of that file

        bool operator==(const WatchListFileRef &) const = default;
    };

    QString name;
    LinkSettings link;
    QList<WatchListFileRef> watchLists;
    // The tables of every watch list, loaded and checked, intervals overridden where asked.
    QList<WatchTableSpec> tables;
    // Elements a write may touch; empty: no writes at all.
    std::vector<AddressRange> allow;
    int statisticsIntervalMs = 5000;
    // A write command older than this (its "time", or how long it waited at the broker while the
    // gateway was away) is refused instead of carried out late.
    int commandMaxAgeSec = 10;

    // A reload restarts a link only when its connection's settings changed.
    bool operator==(const GatewayConnectionConfig &) const = default;

    // Whether `address` lies in one of the allowlist's ranges.
    bool allows(const Address &address) const;
    int itemCount() const;
    // The alarms its watch lists define (issue 50).
    int alarmCount() const;
    // The items recorded in the history (issue 51): those with a history setting, or every one
    // when `recordAll`.
    int historyCount(bool recordAll) const;
};

// The gateway's configuration file: versioned JSON (docs/gateway.md has the reference)
//   {"format":"fatek-gateway","version":1,"broker":{"url":"mqtt://127.0.0.1:1883",...},
//    "prefix":"fatek","readOnly":false,"connections":[{"name":"line1","link":{...},
//    "watchLists":[{"file":"line1.json","intervalMs":1000}],"allow":["R100..R199"],
//    "statisticsIntervalMs":5000}],"homeAssistant":{"discovery":true,"prefix":"homeassistant"},
//    "alarmJournal":"alarms.db","history":{"store":"history.db","recordAll":true,
//    "heartbeatS":600,"retention":{"days":30}}}
// Everything is checked when loading; an error names its place ("connection 2 (line1): link:
// port 70000 is out of range (1..65535)"). Watch lists and the password file are read relative
// to the configuration file.
struct GatewayConfig
{
    static constexpr const char *FormatMarker = "fatek-gateway";
    static constexpr int CurrentVersion = 1;
    static constexpr int MinStatisticsIntervalMs = 100;
    static constexpr int MaxStatisticsIntervalMs = 3600000;

    // Home Assistant's MQTT discovery (HomeAssistantDiscovery): off unless asked for.
    struct HomeAssistant
    {
        bool discovery = false;
        QString prefix = QStringLiteral("homeassistant"); // Home Assistant's discovery prefix

        bool operator==(const HomeAssistant &) const = default;
    };

    // The history (issue 51, docs/history.md): what the items did, kept by a HistoryRecorder per
    // connection in one store. Items with a "history" setting in their watch list are recorded,
    // and every item when recordAll names the setting for the others.
    struct History
    {
        // An SQLite file (absolute: "store" relative to the configuration file, else
        // defaultHistoryStore()) or a PostgreSQL URL ("postgresql://fatek@db/plant"; its password
        // from ~/.pgpass or $PGPASSWORD, never in this file).
        QString store;
        std::optional<HistorySetting> recordAll;
        // 30 days unless "retention" says otherwise ({"days":0}: kept for ever).
        HistoryRetention retention{30LL * 24 * 3600, 0};

        bool operator==(const History &) const = default;
    };

    MqttBrokerSettings broker;
    QString prefix = QStringLiteral("fatek");
    bool readOnly = false;
    HomeAssistant homeAssistant;
    QList<GatewayConnectionConfig> connections;
    // The alarm journal's file (AlarmJournal: every alarm event, and the states that come back
    // after a restart), absolute: "alarmJournal" relative to the configuration file, else
    // defaultAlarmJournal(). Opened only when some connection has alarms.
    QString alarmJournal;
    History history;

    int alarmCount() const;
    // The items recorded, of every connection; the store is opened only when there are some.
    int historyCount() const;
    // Where the journal goes when the configuration names none: the service's state directory
    // (systemd's StateDirectory= sets $STATE_DIRECTORY, /var/lib/fatek-gateway in the packaged
    // unit, where the hardened unit may write), else beside the configuration file.
    static QString defaultAlarmJournal(const QString &baseDirectory);
    // The history's file when the configuration names none: history.db where the journal goes.
    static QString defaultHistoryStore(const QString &baseDirectory);

    // `baseDirectory`: where relative file names start.
    static Result<GatewayConfig> load(const QByteArray &json, const QString &baseDirectory);
    static Result<GatewayConfig> loadFromFile(const QString &path);
};

} // namespace Fatek
