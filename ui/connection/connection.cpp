#include "connection.h"

#include "coretext.h"

namespace Fatek {

Connection::Connection(const SavedConnection &saved, QObject *parent)
    : QObject(parent)
    , m_saved(saved)
    , m_session(new Session(saved.settings, this))
{
    connect(m_session, &Session::linkStateChanged, this,
            [this](LinkState state, const QString &reason) {
                m_state = state;
                m_reason = reason;
                Q_EMIT linkStateChanged(state, reason);
                Q_EMIT changed();
            });
    connect(m_session, &Session::statisticsChanged, this,
            [this](const SessionStatistics &statistics) {
                m_statistics = statistics;
                Q_EMIT changed();
            });
    connect(m_session, &Session::values, this, &Connection::values);
    // Requests per second over the last second; a timer so the rate falls to 0 when idle.
    m_rateTimer.setInterval(1000);
    connect(&m_rateTimer, &QTimer::timeout, this, &Connection::updateRate);
    m_rateTimer.start();
    m_rateClock.start();
}

Connection::~Connection()
{
    // The session's destructor stops its thread; nothing may poll into a half-destroyed object.
    disconnect(m_session, nullptr, this, nullptr);
}

void Connection::setStation(quint8 station)
{
    if (m_saved.station == station)
        return;
    m_saved.station = station;
    Q_EMIT changed();
}

quint64 Connection::errorCount() const
{
    const StationStatistics &t = m_statistics.total;
    return t.timeouts + t.checksumErrors + t.plcErrors;
}

QList<quint8> Connection::silentStations() const
{
    QList<quint8> silent;
    if (m_state != LinkState::Connected)
        return silent; // a link that is down says so itself
    for (auto it = m_statistics.stations.cbegin(); it != m_statistics.stations.cend(); ++it) {
        if (it.value().unanswered > 0 && it.key() != 0)
            silent << it.key();
    }
    return silent;
}

QString Connection::stateText() const
{
    const QString state = CoreText::linkState(m_state);
    const QList<quint8> silent = silentStations();
    if (silent.isEmpty())
        return state;
    QStringList numbers;
    for (quint8 s : silent)
        numbers << QString::number(s);
    return tr("%1, no answer from station %2").arg(state, numbers.join(QStringLiteral(", ")));
}

void Connection::open()
{
    m_session->open();
}

void Connection::close()
{
    m_session->close();
}

void Connection::setPollEntries(const QObject *owner, const QList<WatchEntry> &entries)
{
    if (entries.isEmpty())
        m_pollEntries.remove(owner);
    else
        m_pollEntries.insert(owner, entries);
    pushWatchList();
}

void Connection::pushWatchList()
{
    QList<WatchEntry> all;
    for (auto it = m_pollEntries.cbegin(); it != m_pollEntries.cend(); ++it)
        all += it.value();
    m_session->setWatchList(all);
}

void Connection::updateRate()
{
    const qint64 ms = m_rateClock.restart();
    const quint64 requests = m_statistics.total.requests;
    const quint64 delta = requests >= m_rateRequests ? requests - m_rateRequests : 0;
    m_rateRequests = requests;
    const double rate
        = ms > 0 ? static_cast<double>(delta) * 1000.0 / static_cast<double>(ms) : 0.0;
    if (rate != m_rate) {
        m_rate = rate;
        Q_EMIT changed();
    }
}

} // namespace Fatek
