#pragma once

#include "core/link/plclink.h"
#include "core/plant/plantconnection.h"
#include "core/protocol/plcstatus.h"
#include "core/session/session.h"
#include "linksettingsio.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <deque>
#include <optional>

namespace Fatek {

// The GUI's view of one plant connection (core/plant): its name and saved settings, the station
// the tools act on, what the PLC there says it is, and the link's state and rates for the
// Connections dock. Tables subscribe their items to plant() as its consumers and write through
// it; the tools that talk to the PLC itself use session(), which only a direct link has.
class Connection : public QObject
{
    Q_OBJECT

public:
    Connection(const SavedConnection &saved, QObject *parent = nullptr);
    ~Connection() override;

    QString name() const { return m_saved.name; }
    SavedConnection saved() const { return m_saved; }
    LinkSettings settings() const { return m_saved.settings; }
    quint8 station() const { return m_saved.station; }
    void setStation(quint8 station);

    PlantConnection *plant() const { return m_plant; }
    PlcLink *link() const { return m_link; }
    // The direct link's session; nullptr when another program owns the PLC link.
    Session *session() const { return m_session; }
    bool isGateway() const { return m_link->kind() == PlcLink::Kind::Gateway; }
    // What the link is, in the UI language ("TCP 10.0.0.5:500, FACON", "MQTT gateway line1 ...").
    QString linkText() const { return m_saved.linkText(); }

    // Operator mode, enforced by the link.
    void setReadOnly(bool readOnly);
    bool isReadOnly() const;
    // Writes accepted and not finished; how long a close waits for them.
    int pendingWrites() const;
    int closeDrainMs() const;
    LinkState linkState() const { return m_plant->linkState(); }
    Message linkReason() const { return m_plant->linkReason(); }
    SessionStatistics statistics() const { return m_statistics; }
    double requestsPerSecond() const { return m_rate; }
    // Timeouts, checksum errors, PLC error answers and link failures.
    quint64 errorCount() const;
    // Connection attempts that failed and open links that broke (refused port, cable pulled).
    quint64 linkFailures() const { return m_plant->linkFailures(); }
    // Whether the link ever came up since open().
    bool hasConnected() const { return m_plant->hasConnected(); }
    // While the link is up: stations whose last request got no answer at all (ascending).
    QList<quint8> silentStations() const;
    // "connected", or "connected, no answer from station 5" when a station is silent.
    QString stateText() const;
    // What the PLC at station() says it is (53, read when the link comes up and when the station
    // changes) and its RUN/STOP state (40, every plcStatusIntervalMs while the link is up).
    std::optional<DetailStatus> plcDetail() const { return m_detail; }
    std::optional<PlcStatus> plcStatus() const { return m_plcStatus; }
    // "FBs-28MC · RUN"; "RUN" alone when the model is unknown; empty before the first answer.
    QString plcText() const;
    static constexpr int plcStatusIntervalMs = 3000;

    void open();
    void close();
    // Closes at once, dropping writes not sent yet.
    void closeDiscard();
    // Connects at once when the link is down (skips the reconnect backoff).
    void reconnectNow();

Q_SIGNALS:
    void changed(); // link state, statistics or rate
    void linkStateChanged(Fatek::LinkState state, const Fatek::Message &reason);
    // Every batch of values the link reported (the tables get theirs as the plant's consumers).
    void itemValues(const QList<Fatek::WatchItemValue> &values);

private:
    void onLinkState(LinkState state, const Message &reason);
    void updateRate();
    void readIdentity();
    void readStatus();

    SavedConnection m_saved;
    PlantConnection *m_plant = nullptr;
    PlcLink *m_link = nullptr;             // m_plant's
    Session *m_session = nullptr;          // m_link's, if it has one
    LinkState m_state = LinkState::Closed; // as last reported, to see it come up
    class RequestTracker *m_plcRequests = nullptr;
    QTimer m_statusTimer;
    std::optional<DetailStatus> m_detail;
    std::optional<PlcStatus> m_plcStatus;
    bool m_statusPending = false;
    SessionStatistics m_statistics;
    QTimer m_rateTimer;
    QElapsedTimer m_rateClock;
    // (ms on m_rateClock, requests counted then) over the last rateWindowMs.
    std::deque<std::pair<qint64, quint64>> m_rateSamples;
    double m_rate = 0;
};

} // namespace Fatek
