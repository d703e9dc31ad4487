#pragma once

#include "linksettingsio.h"
#include "session.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QTimer>

namespace Fatek {

// One open link in the GUI: a named Session, the station tools act on, link state and rates.
// Several watch tables may poll through one connection: each owner hands its entries in and the
// connection gives the session their union (the session has a single watch list).
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

    Session *session() const { return m_session; }
    LinkState linkState() const { return m_state; }
    QString linkReason() const { return m_reason; }
    SessionStatistics statistics() const { return m_statistics; }
    double requestsPerSecond() const { return m_rate; }
    // Timeouts, checksum errors and PLC error answers.
    quint64 errorCount() const;
    // While the link is up: stations whose last request got no answer at all (ascending).
    QList<quint8> silentStations() const;
    // "connected", or "connected, no answer from station 5" when a station is silent.
    QString stateText() const;

    void open();
    void close();

    // Replaces what `owner` polls (an empty list removes it).
    void setPollEntries(const QObject *owner, const QList<WatchEntry> &entries);

Q_SIGNALS:
    void changed(); // link state, statistics or rate
    void linkStateChanged(Fatek::LinkState state, const QString &reason);
    void values(const QList<Fatek::WatchValue> &values);

private:
    void updateRate();
    void pushWatchList();

    SavedConnection m_saved;
    Session *m_session;
    LinkState m_state = LinkState::Closed;
    QString m_reason;
    SessionStatistics m_statistics;
    QHash<const QObject *, QList<WatchEntry>> m_pollEntries;
    QTimer m_rateTimer;
    QElapsedTimer m_rateClock;
    quint64 m_rateRequests = 0;
    double m_rate = 0;
};

} // namespace Fatek
